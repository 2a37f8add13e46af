#pragma once
// Live thermal compensation (docs/live-compensation.md): the screw model runs online, one
// step per sample interval, and at a set update interval turns its thermal
// error into a correction: a table over the travel (for a controller that
// takes a table) and one offset at the working position (for an external
// offset such as LinuxCNC's axis.L.eoffset). A correction is applied only
// when the machine is not cutting; an update that falls due mid-cut waits for
// the cut to end. Each update changes each value by at most a set amount, so a
// big thermal change reaches the machine over several updates, never as a jump.
//
// Sign: the model's thermal error is actual − target (µm), the correction the
// controller adds is its negative, as in CompensationTable.h.

#include <optional>
#include <vector>

#include "core/domain/MachineState.h"
#include "core/physics/ScrewThermalModel.h"

namespace driftlab::compensation {

struct LiveSettings {
    double update_interval_s = 60;
    /// Where the table is evaluated, ascending (mm); may be empty.
    std::vector<double> table_positions_mm;
    /// Where the single live offset is evaluated: the working zone (mm).
    double offset_position_mm = 0;
    /// The largest change of any value per applied update (µm, > 0).
    double max_change_um = 5;

    bool isValid(QString* why) const;
};

/// One applied correction.
struct LiveUpdate {
    double time_s = 0;     ///< model time at which it was applied
    double due_s = 0;      ///< when it fell due; time_s − due_s is the wait for a safe state
    double offset_um = 0;  ///< correction at offset_position_mm
    /// The model's full correction at offset_position_mm, before the change
    /// limit: what `offset_um` approaches while `limited`.
    double target_offset_um = 0;
    std::vector<double> table_correction_um;  ///< per table position
    /// The model's full correction was held back by max_change_um; the rest
    /// follows with the next updates.
    bool limited = false;
};

class LiveThermalCompensation {
public:
    /// The screw starts uniformly at `initial_C`, which is also the reference
    /// of the thermal error: the correction is zero until the screw warms.
    /// Throws std::invalid_argument on invalid settings or parameters.
    LiveThermalCompensation(const physics::ScrewThermalParameters& parameters, double initial_C,
                            LiveSettings settings);

    /// Advances the model by one step; `state` is the machine state at the
    /// end of the step. Returns the update applied at the end of this step,
    /// if one was due and the machine is not cutting.
    std::optional<LiveUpdate> step(const physics::StepConditions& conditions, MachineState state);

    /// The correction the model asks for now, before limits and gating (µm).
    double targetOffsetUm() const;
    /// What is applied: zero until the first update.
    const LiveUpdate& applied() const { return m_applied; }
    bool updatePending() const { return m_pendingSince_s.has_value(); }

private:
    LiveUpdate makeUpdate(double due_s);

    physics::ScrewThermalModel m_model;
    LiveSettings m_settings;
    LiveUpdate m_applied;
    double m_nextDue_s = 0;
    std::optional<double> m_pendingSince_s;
    std::vector<double> m_positions_mm;  ///< table positions then the offset position
};

}  // namespace driftlab::compensation
