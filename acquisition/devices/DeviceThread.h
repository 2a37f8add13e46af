#pragma once
// The thread a polled device runs on: owns the QThread and its DeviceWorker,
// starts it once and stops it within a bound. Its signals arrive on the
// thread that created it (queued from the worker). The typed facades
// (DeviceFacade) hold one and forward its signals with the reading unpacked
// from its QVariant.

#include <QObject>
#include <QVariant>

#include "acquisition/devices/DeviceWorker.h"

class QThread;

namespace driftlab::devices {

class DeviceThread : public QObject {
    Q_OBJECT
public:
    /// `name` names the thread (e.g. "device 10.0.0.5:502").
    DeviceThread(PolledDeviceFactory make_device, const QString& name, DeviceWorkerOptions options,
                 QObject* parent = nullptr);
    /// Stops with stopAndWait(kDefaultStopTimeoutMs).
    ~DeviceThread() override;

    static constexpr int kDefaultStopTimeoutMs = 5000;

    /// Starts polling; once (a stopped device is not restarted).
    void start();
    /// Stop flag, a queued shutdown (closes the link, quits the thread), a
    /// wait of at most `timeout_ms`. False when the worker is still inside a
    /// request then; the thread is left to end on its own (it is bounded by
    /// the response timeout) and deletes itself — never terminate(), which
    /// could leave libmodbus or a lock half-done.
    bool stopAndWait(int timeout_ms = kDefaultStopTimeoutMs);
    bool isRunning() const;

signals:
    void readingReady(const QVariant& reading);
    void errorOccurred(const QString& message);
    void gap(const QDateTime& from_utc, const QDateTime& to_utc);
    void healthChanged(driftlab::devices::DeviceHealth health);
    void attemptFailed(int attempt, double next_retry_s);

private:
    QThread* m_thread = nullptr;
    DeviceWorker* m_worker = nullptr;
    bool m_started = false;
};

}  // namespace driftlab::devices
