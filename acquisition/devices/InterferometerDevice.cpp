#include "acquisition/devices/InterferometerDevice.h"

namespace driftlab::devices {
namespace {

/// The stream behind the worker's poll: each poll reads one slice.
class InterferometerLink : public PolledDevice {
public:
    explicit InterferometerLink(InterferometerStreamOptions options)
        : m_connection(std::move(options)) {}

    bool connect(QString* error) override {
        m_pendingError.clear();
        return m_connection.open(error);
    }

    std::optional<PolledReading> poll(QString* error) override {
        if (!m_pendingError.isEmpty()) {
            *error = std::exchange(m_pendingError, {});
            return std::nullopt;
        }
        InterferometerBatch batch;
        const auto status = m_connection.read(
            InterferometerDevice::kReadSlice_ms,
            [&batch](const interferometer::CorrectedReading& reading) {
                batch.readings.push_back({QDateTime::currentDateTimeUtc(), reading});
            });
        if (status != InterferometerConnection::Status::Open) {
            const QString why = status == InterferometerConnection::Status::Ended
                                    ? QStringLiteral(
                                          "the interferometer at %1 ended its stream ('end' line) "
                                          "after %2 reading(s); reconnecting for the next")
                                          .arg(m_connection.peer())
                                          .arg(m_connection.readings())
                                    : m_connection.error();
            // Readings of the last slice are delivered first; the failure at the next poll.
            if (batch.readings.empty()) {
                *error = why;
                return std::nullopt;
            }
            m_pendingError = why;
        }
        if (batch.readings.empty()) return PolledReading{};  // the link is fine, nothing new
        const QDateTime last = batch.readings.back().time_utc;
        return PolledReading{last, QVariant::fromValue(std::move(batch))};
    }

    void close() override { m_connection.close(); }

private:
    InterferometerConnection m_connection;
    QString m_pendingError;
};

}  // namespace

InterferometerDevice::InterferometerDevice(InterferometerStreamOptions stream,
                                           DeviceWorkerOptions options, QObject* parent)
    : DeviceFacade([stream] { return std::make_unique<InterferometerLink>(stream); },
                   QStringLiteral("interferometer %1:%2").arg(stream.host).arg(stream.port),
                   [options] {
                       // The read slice paces the stream; the worker polls again at once.
                       DeviceWorkerOptions o = options;
                       o.poll_interval_s = 0;
                       return o;
                   }(),
                   parent) {
    qRegisterMetaType<InterferometerBatch>();
    forwardReadings<InterferometerBatch>(this);
}

}  // namespace driftlab::devices
