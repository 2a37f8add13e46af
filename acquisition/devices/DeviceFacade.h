#pragma once
// What the typed device facades (TemperatureDevice, ControllerDevice,
// InterferometerDevice) share: the DeviceThread their worker polls on, its
// start and bounded stop, and the signals every device has. Each facade adds
// only readingReady with its own reading type (forwardReadings).

#include <QObject>

#include "acquisition/devices/DeviceThread.h"

namespace driftlab::devices {

class DeviceFacade : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultStopTimeoutMs = DeviceThread::kDefaultStopTimeoutMs;

    /// Starts polling; once per device (a stopped device is not restarted).
    void start() { m_thread.start(); }
    /// DeviceThread::stopAndWait: bounded, never terminate().
    bool stopAndWait(int timeout_ms = kDefaultStopTimeoutMs) {
        return m_thread.stopAndWait(timeout_ms);
    }
    bool isRunning() const { return m_thread.isRunning(); }

signals:
    void errorOccurred(const QString& message);
    void gap(const QDateTime& from_utc, const QDateTime& to_utc);
    void healthChanged(driftlab::devices::DeviceHealth health);
    void attemptFailed(int attempt, double next_retry_s);

protected:
    DeviceFacade(PolledDeviceFactory make_device, const QString& name, DeviceWorkerOptions options,
                 QObject* parent);

    /// Emits `facade`'s readingReady with each reading unpacked as `Reading`.
    /// Both live on one thread, so this is direct; the thread crossing is
    /// DeviceThread's queued connection to its worker.
    template <class Reading, class Facade>
    void forwardReadings(Facade* facade) {
        QObject::connect(&m_thread, &DeviceThread::readingReady, facade,
                         [facade](const QVariant& reading) {
                             emit facade->readingReady(reading.value<Reading>());
                         });
    }

private:
    DeviceThread m_thread;
};

}  // namespace driftlab::devices
