#pragma once
// Polling a device off the GUI thread (STYLE.md, acquisition row, after
// QGroundControl's link workers): DeviceWorker lives on its own QThread, polls
// a PolledDevice and talks only through queued signals; DeviceThread (in
// DeviceThread.h) owns the thread. A lost device is reconnected with a
// doubling backoff; each connect cycle (from losing the data to getting it
// back) reports one error, not one per failed attempt, and a gap (from, to)
// when data resumes.

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QVariant>
#include <atomic>
#include <memory>

#include "acquisition/devices/PolledDevice.h"

class QTimer;

namespace driftlab::devices {

enum class DeviceHealth {
    Connecting,    ///< started, no reading yet
    Connected,     ///< readings arrive
    Reconnecting,  ///< the link failed; retrying with backoff
    Failed,        ///< gave up after max_attempts failed attempts in one cycle
    Stopped,
};
QString toString(DeviceHealth health);

struct DeviceWorkerOptions {
    double poll_interval_s = 1.0;
    double backoff_initial_s = 0.2;
    double backoff_max_s = 5.0;
    /// Bounds the connect and each request; a poll takes at most blocks × this.
    double response_timeout_s = 1.0;
    /// Failed attempts in one cycle before giving up (Failed); 0 = never give up.
    int max_attempts = 0;
};

/// The worker: create it, move it to a thread, call start() there.
class DeviceWorker : public QObject {
    Q_OBJECT
public:
    /// `make_device` is called in start(), on the worker's thread.
    DeviceWorker(PolledDeviceFactory make_device, DeviceWorkerOptions options);
    ~DeviceWorker() override;

    /// Thread-safe: makes the worker stop before its next connect or poll.
    void requestStop() { m_stop = true; }

public slots:
    void start();
    /// Stops the timer and closes the link (on the worker's thread).
    void shutdown();

signals:
    /// The device's reading (PolledReading::value).
    void readingReady(const QVariant& reading);
    void errorOccurred(const QString& message);
    /// No data between `from_utc` (last reading before) and `to_utc` (first after).
    void gap(const QDateTime& from_utc, const QDateTime& to_utc);
    void healthChanged(driftlab::devices::DeviceHealth health);
    /// Every failed connect or poll, with its number in the cycle and the wait
    /// before the next attempt (0 when giving up). Errors are reported once
    /// per cycle; this lets a watcher see the retries.
    void attemptFailed(int attempt, double next_retry_s);

private:
    void connectNow();
    void pollNow();
    void failed(const QString& message);
    void setHealth(DeviceHealth health);

    PolledDeviceFactory m_make_device;
    DeviceWorkerOptions m_options;
    std::unique_ptr<PolledDevice> m_device;  // created on the worker's thread
    QTimer* m_timer = nullptr;
    std::atomic<bool> m_stop{false};
    DeviceHealth m_health = DeviceHealth::Stopped;
    double m_backoff_s = 0;
    int m_attempts = 0;             ///< failed attempts in this cycle
    bool m_error_reported = false;  ///< this cycle's one error is out
    QDateTime m_last_reading_utc;   ///< invalid before the first reading
    bool m_outage = false;          ///< data lost since m_last_reading_utc
    bool m_link_up = false;         ///< the timer polls when true, else reconnects
};

}  // namespace driftlab::devices

Q_DECLARE_METATYPE(driftlab::devices::DeviceHealth)
