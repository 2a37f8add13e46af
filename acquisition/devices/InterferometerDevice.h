#pragma once
// The interferometer as a device of the real rig: its line stream read on its
// own thread (DeviceThread), a slice at a time, so a stop is never held up
// longer than one slice. It keeps the polled devices' rules (DeviceWorker):
// a stream that ends or breaks is reconnected with a doubling backoff, one
// error per outage, a gap when readings resume.

#include <QDateTime>
#include <QObject>
#include <vector>

#include "acquisition/devices/DeviceThread.h"
#include "acquisition/devices/InterferometerConnection.h"

namespace driftlab::devices {

struct TimedInterferometerReading {
    QDateTime time_utc;  ///< when its line arrived
    CorrectedReading reading;
};

/// The readings that arrived during one slice of the stream.
struct InterferometerBatch {
    std::vector<TimedInterferometerReading> readings;
};

class InterferometerDevice : public QObject {
    Q_OBJECT
public:
    /// Longest a read blocks the worker: bounds the stop.
    static constexpr int kReadSlice_ms = 200;

    explicit InterferometerDevice(InterferometerStreamOptions stream,
                                  DeviceWorkerOptions options = {}, QObject* parent = nullptr);

    void start() { m_thread.start(); }
    bool stopAndWait(int timeout_ms = DeviceThread::kDefaultStopTimeoutMs) {
        return m_thread.stopAndWait(timeout_ms);
    }
    bool isRunning() const { return m_thread.isRunning(); }

signals:
    void readingReady(const driftlab::devices::InterferometerBatch& batch);
    void errorOccurred(const QString& message);
    void gap(const QDateTime& from_utc, const QDateTime& to_utc);
    void healthChanged(driftlab::devices::DeviceHealth health);
    void attemptFailed(int attempt, double next_retry_s);

private:
    DeviceThread m_thread;
};

}  // namespace driftlab::devices

Q_DECLARE_METATYPE(driftlab::devices::InterferometerBatch)
