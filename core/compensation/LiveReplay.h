#pragma once
// A measured run replayed as if it were live: its ambient, torque and motion
// drive LiveThermalCompensation step by step, as the acquisition would, and
// the corrections it applies are scored against the thermal error the
// interferometer measured in that run. On a run the model was not fitted on,
// this is the gain a test engineer can expect from live compensation, with
// its real delays (update interval, waiting for cuts to end, change limit).

#include <functional>

#include "core/compensation/LiveThermalCompensation.h"
#include "core/models/ScrewRunSimulation.h"
#include "core/models/ThermalErrorData.h"

namespace driftlab::compensation {

struct LiveReplayOptions {
    LiveSettings settings;
    double dt_s = 2;  ///< model step, the acquisition's sample interval
    /// The machine state at a time of the run; default: moving while the
    /// axis moves, idle in dwells.
    std::function<MachineState(double time_s)> state_at;
    /// Called with every applied update (e.g. to write it to the controller);
    /// returning false cancels the replay.
    std::function<bool(const LiveUpdate&)> on_update;
    /// Asked at every model step; true cancels the replay between updates.
    std::function<bool()> cancelled;
    /// What an extended model does to the logged inputs before it steps
    /// (the motor's heat reaching the screw late). It must be causal, each
    /// step from earlier samples only, as it would be on live data.
    std::function<void(models::ScrewRunInputs&)> online_inputs;
};

struct LiveReplayResult {
    std::vector<LiveUpdate> updates;
    /// RMS of the measured thermal error, and of what is left of it with the
    /// correction applied at the time of each reading (table interpolated
    /// linearly at the reading's target), µm.
    double rms_before_um = 0;
    double rms_after_um = 0;
    /// The same with only the working-position offset applied everywhere:
    /// what a controller with a single external offset gets.
    double rms_after_offset_um = 0;
    std::size_t readings = 0;
    bool cancelled = false;
    QString error;  ///< empty on success
    bool ok() const { return error.isEmpty(); }
};

/// The state a replay assumes without a controller: moving on a motion
/// segment that moves, idle otherwise.
MachineState stateFromMotion(const std::vector<MotionSegment>& motion, double time_s);

/// Replays `run` (positioning error target) on the screw `parameters`.
LiveReplayResult replayLive(const models::RunData& run,
                            const physics::ScrewThermalParameters& parameters,
                            LiveReplayOptions options);

}  // namespace driftlab::compensation
