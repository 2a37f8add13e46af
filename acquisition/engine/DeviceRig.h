#pragma once
// A real rig behind the TestRig interface: a temperature module and,
// optionally, the controller link, each polled over Modbus by its own worker
// thread (devices/DeviceWorker), and the interferometer's line stream read on
// its own thread (devices/InterferometerDevice), in real time. The
// machine runs the procedure's motion from its own NC programme; DriftLab
// logs what the devices read on the procedure's clock. A device that stops
// answering leaves NaN in its columns and a gap in the event log, and the
// watchdog reconnects it; the other devices keep logging.

#include <QDateTime>
#include <QString>

#include "acquisition/devices/ChannelRegisterMap.h"
#include "acquisition/devices/InterferometerConnection.h"
#include "acquisition/engine/TestRig.h"
#include "acquisition/modbus/ModbusUrl.h"

namespace driftlab::engine {

struct DeviceRigSpec {
    modbus::ModbusUrl temperature_url;
    devices::ChannelRegisterMap temperature_map;
    /// Position, feed, torque and machine state (register map block 0).
    std::optional<modbus::ModbusUrl> controller_url;
    /// The interferometer's line stream (docs/interferometer.md); its readings
    /// are matched to the planned targets (TargetMatcher).
    std::optional<devices::InterferometerStreamOptions> interferometer;
    /// How far a reading's position may be from a planned target, mm.
    double target_tolerance_mm = 0.05;
    double poll_interval_s = 1.0;
    /// How long the temperature module and the controller may take to give
    /// their first reading before the run fails: a device that never answers
    /// is a wrong address, not an outage to wait out.
    double connect_timeout_s = 30.0;
    /// Machine, screw, travel and the channels (ids as in the map, with their
    /// roles); without it, a campaign with the map's channels as `other`.
    std::optional<Campaign> campaign_template;
};

class DeviceRig : public TestRig {
public:
    explicit DeviceRig(DeviceRigSpec spec);
    QString describe() const override;
    bool realTime() const override { return true; }
    Campaign campaignHeader(const std::vector<procedures::PlannedRun>& runs) const override;
    std::unique_ptr<RunSource> open(const procedures::PlannedRun& run, std::size_t index,
                                    const std::vector<QString>& columns, QString* error) override;

private:
    DeviceRigSpec m_spec;
};

}  // namespace driftlab::engine
