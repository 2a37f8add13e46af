#pragma once
// The interferometer as a device of the real rig: its line stream read on its
// own thread (DeviceThread), a slice at a time, so a stop is never held up
// longer than one slice. It keeps the polled devices' rules (DeviceWorker):
// a stream that ends or breaks is reconnected with a doubling backoff, one
// error per outage, a gap when readings resume.

#include <QDateTime>
#include <QObject>
#include <vector>

#include "acquisition/devices/DeviceFacade.h"
#include "acquisition/devices/InterferometerConnection.h"

namespace driftlab::devices {

struct TimedInterferometerReading {
    QDateTime time_utc;  ///< when its line arrived
    interferometer::CorrectedReading reading;
};

/// The readings that arrived during one slice of the stream.
struct InterferometerBatch {
    std::vector<TimedInterferometerReading> readings;
};

class InterferometerDevice : public DeviceFacade {
    Q_OBJECT
public:
    /// Longest a read blocks the worker: bounds the stop.
    static constexpr int kReadSlice_ms = 200;

    explicit InterferometerDevice(InterferometerStreamOptions stream,
                                  DeviceWorkerOptions options = {}, QObject* parent = nullptr);

signals:
    void readingReady(const driftlab::devices::InterferometerBatch& batch);
};

}  // namespace driftlab::devices

Q_DECLARE_METATYPE(driftlab::devices::InterferometerBatch)
