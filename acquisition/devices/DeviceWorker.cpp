#include "acquisition/devices/DeviceWorker.h"

#include <QLoggingCategory>
#include <QThread>
#include <QTimer>
#include <algorithm>
#include <cmath>

namespace driftlab::devices {

Q_LOGGING_CATEGORY(lcDevice, "driftlab.acquisition.devices")

QString toString(DeviceHealth health) {
    switch (health) {
        case DeviceHealth::Connecting:
            return QStringLiteral("connecting");
        case DeviceHealth::Connected:
            return QStringLiteral("connected");
        case DeviceHealth::Reconnecting:
            return QStringLiteral("reconnecting");
        case DeviceHealth::Failed:
            return QStringLiteral("failed");
        case DeviceHealth::Stopped:
            return QStringLiteral("stopped");
    }
    return {};
}

namespace {
int toMs(double seconds) {
    return int(std::lround(std::clamp(seconds, 0.0, 3600.0) * 1000));
}
}  // namespace

DeviceWorker::DeviceWorker(PolledDeviceFactory make_device, DeviceWorkerOptions options)
    : m_make_device(std::move(make_device)), m_options(options) {
    // A child, so it moves to the worker's thread with the worker.
    m_timer = new QTimer(this);
    m_timer->setSingleShot(true);
    connect(m_timer, &QTimer::timeout, this, [this] { m_link_up ? pollNow() : connectNow(); });
}

DeviceWorker::~DeviceWorker() = default;

void DeviceWorker::start() {
    // The libmodbus context is made here, on the thread that will use it.
    m_device = m_make_device();
    m_backoff_s = m_options.backoff_initial_s;
    setHealth(DeviceHealth::Connecting);
    connectNow();
}

void DeviceWorker::shutdown() {
    m_stop = true;
    m_timer->stop();
    if (m_device) m_device->close();
    m_link_up = false;
    setHealth(DeviceHealth::Stopped);
    // Quitting here, not from the facade, so this runs before the loop ends:
    // quit() from outside may drop events still queued.
    thread()->quit();
}

void DeviceWorker::setHealth(DeviceHealth health) {
    if (health == m_health) return;
    m_health = health;
    emit healthChanged(health);
}

void DeviceWorker::connectNow() {
    if (m_stop) return;
    QString error;
    if (!m_device->connect(&error)) return failed(error);
    m_link_up = true;
    pollNow();
}

void DeviceWorker::pollNow() {
    if (m_stop) return;
    QString error;
    std::optional<PolledReading> reading = m_device->poll(&error);
    if (!reading) return failed(error);
    if (!reading->time_utc.isValid()) {
        // A pushing device with nothing new: not data (an outage goes on), not a failure.
        m_timer->start(toMs(m_options.poll_interval_s));
        return;
    }
    if (m_outage && m_last_reading_utc.isValid()) emit gap(m_last_reading_utc, reading->time_utc);
    // The cycle ends with data, not with a connect: a device that accepts
    // TCP but never answers stays one cycle with one error.
    m_outage = false;
    m_error_reported = false;
    m_attempts = 0;
    m_backoff_s = m_options.backoff_initial_s;
    m_last_reading_utc = reading->time_utc;
    setHealth(DeviceHealth::Connected);
    emit readingReady(reading->value);
    m_timer->start(toMs(m_options.poll_interval_s));
}

void DeviceWorker::failed(const QString& message) {
    m_device->close();
    m_link_up = false;
    m_outage = true;
    ++m_attempts;
    if (!m_error_reported) {
        m_error_reported = true;
        qCWarning(lcDevice) << message;
        emit errorOccurred(message);
    }
    if (m_options.max_attempts > 0 && m_attempts >= m_options.max_attempts) {
        emit attemptFailed(m_attempts, 0.0);
        setHealth(DeviceHealth::Failed);
        return;
    }
    const double retry_s = m_backoff_s;
    emit attemptFailed(m_attempts, retry_s);
    setHealth(m_last_reading_utc.isValid() ? DeviceHealth::Reconnecting : DeviceHealth::Connecting);
    m_backoff_s = std::min(m_backoff_s * 2, m_options.backoff_max_s);
    m_timer->start(toMs(retry_s));
}

}  // namespace driftlab::devices
