#pragma once
// The event-log entries of a device that stops answering and comes back, as
// every rig writes them: a real device (DeviceRunSource, from its worker's
// error and gap signals) and the simulated rig's temperature module
// (SimulatedRig, from RigSpec::module_outages). The GUI's device health and
// the tests read these words.

#include "acquisition/engine/TestRig.h"

namespace driftlab::engine {

/// The source name of a temperature module at `endpoint` (HOST:PORT, a
/// serial device, or "sim" for the simulated rig's).
QString temperatureModuleSource(const QString& endpoint);

/// The device stopped answering: an error with the reason, once per outage.
SourceEvent deviceLostEvent(const QString& source, const QString& reason);

/// The device answers again: a warning with the span it gave no data, from
/// its last reading before to its first after.
SourceEvent deviceBackEvent(const QString& source, const QString& from, const QString& to,
                            double seconds);

}  // namespace driftlab::engine
