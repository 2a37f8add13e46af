#pragma once
// The pre-run check of a real rig's devices: each one answers one read within
// a short timeout, and the temperature module's first readings are plausible
// (the sensor-health range). Blocks its thread for up to the timeout per
// device: the GUI calls it on a worker.

#include <QString>
#include <vector>

#include "acquisition/engine/RigFactory.h"
#include "core/sensors/SensorHealthSettings.h"

namespace driftlab::engine {

struct DeviceProbeResult {
    QString device;  ///< as the event log names it, e.g. "temperature module 10.0.0.5:502"
    bool ok = false;
    QString message;  ///< what was read, or why it failed
};

/// One result per device of `options` (a Modbus rig); a simulated rig has none.
std::vector<DeviceProbeResult> probeDevices(const RigOptions& options,
                                            const sensors::SensorHealthSettings& settings,
                                            double timeout_s = 1.0);

}  // namespace driftlab::engine
