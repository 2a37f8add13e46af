#pragma once
// A temperature module polled on its own thread (DeviceThread): readings,
// errors once per connect cycle, gaps and health as queued signals, over
// Modbus TCP or RTU as the URL says (docs/devices.md).

#include <QObject>

#include "acquisition/devices/DeviceThread.h"
#include "acquisition/devices/TemperatureModule.h"

namespace driftlab::devices {

class TemperatureDevice : public QObject {
    Q_OBJECT
public:
    TemperatureDevice(ChannelRegisterMap map, modbus::ModbusUrl url,
                      DeviceWorkerOptions options = {}, QObject* parent = nullptr);

    static constexpr int kDefaultStopTimeoutMs = DeviceThread::kDefaultStopTimeoutMs;

    /// Starts polling; once per device (a stopped device is not restarted).
    void start() { m_thread.start(); }
    /// DeviceThread::stopAndWait: bounded, never terminate().
    bool stopAndWait(int timeout_ms = kDefaultStopTimeoutMs) {
        return m_thread.stopAndWait(timeout_ms);
    }
    bool isRunning() const { return m_thread.isRunning(); }

signals:
    void readingReady(const driftlab::devices::TemperatureReading& reading);
    void errorOccurred(const QString& message);
    void gap(const QDateTime& from_utc, const QDateTime& to_utc);
    void healthChanged(driftlab::devices::DeviceHealth health);
    void attemptFailed(int attempt, double next_retry_s);

private:
    DeviceThread m_thread;
};

}  // namespace driftlab::devices
