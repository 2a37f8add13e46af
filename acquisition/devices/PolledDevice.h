#pragma once
// What DeviceWorker polls: a device that connects, gives one reading per poll
// and closes. The temperature module and the controller link implement it;
// the worker holds the reconnect policy, so every polled device gets the same
// watchdog behaviour (docs/devices.md, "Polling and reconnecting").

#include <QDateTime>
#include <QString>
#include <QVariant>
#include <functional>
#include <memory>
#include <optional>

namespace driftlab::devices {

/// One poll's result: when it was taken (for gaps) and the device's own
/// reading type in a QVariant, so one worker carries any device's readings
/// through queued signals. A pushing device (the interferometer's stream) may
/// have nothing new at a poll while its link is fine: it returns a
/// PolledReading with an invalid time_utc, which is neither data nor a failure.
struct PolledReading {
    QDateTime time_utc;
    QVariant value;
};

class PolledDevice {
public:
    virtual ~PolledDevice() = default;
    /// Connects (again). False with `error`.
    virtual bool connect(QString* error) = 0;
    /// One reading, or nullopt with `error` when the link failed; the device
    /// closes its link then.
    virtual std::optional<PolledReading> poll(QString* error) = 0;
    virtual void close() = 0;
};

/// Makes the device on the worker's thread: a libmodbus context belongs to
/// the thread that created it.
using PolledDeviceFactory = std::function<std::unique_ptr<PolledDevice>()>;

}  // namespace driftlab::devices
