#pragma once
// The screw simulation (core/physics) driven by a measured run: its motion,
// its ambient channel, its torque; read out where the run has sensors on the
// screw (nut flank, bearing seats) and where the interferometer measured.
// Prepared once per run, then simulated for as many parameter sets as an
// identification needs.

#include <memory>
#include <vector>

#include "core/models/ThermalErrorData.h"
#include "core/physics/ScrewThermalModel.h"

namespace driftlab::models {

/// A temperature channel on the screw that the simulation predicts.
struct ScrewSensorSeries {
    QString channel_id;
    ChannelRole role = ChannelRole::Other;
    double position_mm = 0;  ///< bearing seats: where the sensor sits
    std::vector<double> time_s;
    std::vector<double> measured_C;
};

struct ScrewRunInputs {
    QString run_id;
    double dt_s = 2;
    double duration_s = 0;
    double initial_C = 20;  ///< the screw soaked in the room: the ambient reading at the start
    std::vector<MotionSegment> motion;
    std::vector<double> ambient_C;                ///< at k·dt, k = 0…steps
    std::vector<double> mean_torque_squared_Nm2;  ///< per step; empty without a torque column
    std::vector<ScrewSensorSeries> sensors;
    /// Rises of the air and structure channels (empty when the campaign has
    /// none), for effects on the interferometer reading.
    Signal air_rise_K, structure_rise_K;
    double dead_path_mm = 0;  ///< interferometer dead path
    /// The motion cut once for the run's screw on the identification grid
    /// (prepareScrewRun with cells > 0); a simulation on another grid cuts it
    /// step by step.
    std::shared_ptr<const physics::NutPath> nut_path;
};

/// Where the simulation's room temperature comes from.
enum class RoomInput {
    Channel,   ///< the campaign's ambient channel, read as logged
    RoomOnly,  ///< the ambient channel where logged, else steady; no sensor on the machine
    Steady,    ///< no temperature channel at all: the room held at its start
};

/// Throws ModelError when the run lacks what the simulation needs: a screw,
/// motion (segments or a position column), an ambient channel (RoomInput::Channel).
/// With RoomInput::Steady no temperature channel is read, the screw sensors included;
/// with RoomInput::RoomOnly the ambient channel alone, when the run logs it.
/// With `cells` > 0 the nut's path is cut for a screw of that many cells, for
/// the many simulations of an identification.
ScrewRunInputs prepareScrewRun(const RunData& run, double dt_s, const QString& model,
                               RoomInput room = RoomInput::Channel, int cells = 0);

/// The screw of the campaign with its geometry and material; heat
/// coefficients from `coefficients` (c_nut, c_b, h, …), numerics from `cells`.
physics::ScrewThermalParameters screwParameters(const RunData& run,
                                                const physics::ScrewThermalParameters& coefficients,
                                                int cells);

struct ScrewRunOutputs {
    std::vector<std::vector<double>> sensor_C;  ///< per ScrewRunInputs::sensors entry
    std::vector<double> error_um;               ///< per requested point
};

/// Simulates the run; thermal error at `points` relative to the run's start.
ScrewRunOutputs simulateScrewRun(const ScrewRunInputs& inputs,
                                 const physics::ScrewThermalParameters& parameters,
                                 const std::vector<PredictionPoint>& points);

}  // namespace driftlab::models
