#pragma once
// The simulated rig: runs the moving-state programme of every run on the screw
// simulation, logs the sensors, the drive and the interferometer as a real
// rig would (noise, quantisation, dropouts, backlash, cold geometric error),
// hides the requested effects, and returns a complete campaign, ready to be
// written as a bundle or stored.

#include <functional>
#include <stdexcept>

#include "core/domain/Campaign.h"
#include "core/physics/ScrewThermalModel.h"
#include "core/rig/RigSpec.h"

namespace driftlab::rig {

struct SimulationCancelled : std::runtime_error {
    SimulationCancelled() : std::runtime_error("simulation cancelled") {}
};

struct SimulationCallbacks {
    /// Progress over the whole campaign, 0…1; return false to cancel
    /// (simulateCampaign then throws SimulationCancelled).
    std::function<bool(double fraction)> progress;
    /// Called at every logged sample with the true screw state, for plots of
    /// what no sensor sees (the temperature field, the true thermal error).
    std::function<void(const QString& run_id, const physics::ScrewThermalModel& screw)> sample;
};

/// The screw parameters the rig really simulates: spec.screw with the
/// physical effects (forced convection, nut heat exponent, motor heat) applied.
physics::ScrewThermalParameters effectiveScrewParameters(const RigSpec& spec);

/// The campaign a rig logs into, without runs: machine, screw, channels and
/// sample columns (with the spindle-test channels when asked).
Campaign rigCampaignHeader(const RigSpec& spec, bool withSpindleChannels);

/// Throws std::invalid_argument on a spec that cannot run: bad screw
/// parameters, a run range outside the travel or the screw, an effect on a
/// channel the rig does not have, no runs, duplicate run ids.
Campaign simulateCampaign(const RigSpec& spec, const SimulationCallbacks& callbacks = {});

}  // namespace driftlab::rig
