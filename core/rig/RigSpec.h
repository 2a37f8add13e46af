#pragma once
// What the simulated rig is and what it runs: the screw and its true heat
// coefficients, the environment, the instruments, the moving states and the
// hidden effects. Defaults give the magnitudes published feed-axis tests
// report: a 40 mm screw with 10 mm lead, about 9 W of nut heat at 800 rpm,
// tens of µm of thermal error at the far end after 2 h.

#include <QString>
#include <vector>

#include "core/domain/Run.h"
#include "core/physics/ScrewThermalParameters.h"
#include "core/rig/RigEffects.h"

namespace driftlab::rig {

/// One moving state of a campaign (a run).
struct MovingStateRun {
    QString id;
    double feed_mm_min = 8000;
    RangeMm range_mm{210, 490};
    double warmup_s = 7200;
    double cooldown_s = 3600;
};

/// The cross-state design of the published robust-modelling study: S1–S3 share
/// a range at three feeds, S4 and S5 change the range at the S1 feed.
std::vector<MovingStateRun> defaultMovingStates();

/// Channel ids of the rig's temperature sensors; the diagnosis must find them
/// by role, so tests rename them.
struct RigChannelNames {
    QString nut = QStringLiteral("T_nut");
    QString bearing_fixed = QStringLiteral("T_bearing_fixed");
    QString bearing_free = QStringLiteral("T_bearing_free");
    QString ambient = QStringLiteral("T_ambient");
    QString air = QStringLiteral("T_air");
    QString structure = QStringLiteral("T_bed");
    std::vector<QString> all() const {
        return {nut, bearing_fixed, bearing_free, ambient, air, structure};
    }
};

/// Servo drive: torque = Coulomb + viscous·ω, plus J·Δω/t_acc while the axis
/// accelerates at a reversal.
struct AxisDriveSpec {
    double coulomb_Nm = 1.1;
    double viscous_Nm_per_rad_s = 0.004;
    double inertia_kg_m2 = 0.0025;
    double acceleration_time_s = 0.08;
    double torque_noise_Nm = 0.03;
};

struct InterferometerSpec {
    double dead_path_mm = 150;
    double noise_um = 0.3;
    double backlash_um = 2.5;             ///< reversal value: + half going up, − half going down
    double pitch_error_amplitude_um = 6;  ///< cold geometric error, periodic part
    double pitch_error_period_mm = 420;
    double lead_error_um_per_m = 10;  ///< cold geometric error, cumulative part
};

struct EnvironmentSpec {
    double ambient_mean_C = 20;
    double ambient_swing_K = 0.5;  ///< amplitude of the slow daily-like swing
    double ambient_period_s = 12 * 3600;
    double run_offset_spread_K = 0.3;  ///< each run starts at a different room temperature
    double air_screw_coupling = 0.3;   ///< air in the beam path warms with the screw …
    double air_lag_s = 900;            ///< … with this lag
    double structure_screw_coupling = 0.25;
    double structure_lag_s = 2400;
};

/// A span of a run in which the rig's temperature module does not answer:
/// every temperature column is missing from `from_s` up to (not including)
/// `to_s`, run time; the controller's columns and the interferometer go on.
struct ModuleOutage {
    QString run_id;
    double from_s = 0;
    double to_s = 0;
    bool operator==(const ModuleOutage&) const = default;
};

struct RigSpec {
    QString campaign_name = QStringLiteral("Simulated X axis, five moving states");
    physics::ScrewThermalParameters screw;  ///< the rig's truth; effects are applied on top
    RangeMm travel_mm{0, 700};
    int targets = 11;
    double sample_interval_s = 10;
    double physics_step_s = 1;
    std::vector<MovingStateRun> runs = defaultMovingStates();
    /// ISO 230-3 spindle runs after the moving states: SP1 … SP<n>, each its own
    /// speed programme (spindleTestProgramme).
    int spindle_runs = 0;
    double probe_noise_um = 0.1;  ///< the spindle runs' drift probes (1 σ)
    RigEffects effects;
    RigChannelNames names;
    AxisDriveSpec drive;
    InterferometerSpec interferometer;
    EnvironmentSpec environment;
    double temperature_noise_K = 0.02;
    double dropout_probability = 0;
    /// The temperature module's outages (ModuleOutage.h), any order.
    std::vector<ModuleOutage> module_outages;
    unsigned seed = 1;
};

}  // namespace driftlab::rig
