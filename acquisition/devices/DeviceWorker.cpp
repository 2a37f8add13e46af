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

DeviceWorker::DeviceWorker(ChannelRegisterMap map, modbus::ModbusUrl url,
                           DeviceWorkerOptions options)
    : m_map(std::move(map)), m_url(std::move(url)), m_options(options) {
    // A child, so it moves to the worker's thread with the worker.
    m_timer = new QTimer(this);
    m_timer->setSingleShot(true);
    connect(m_timer, &QTimer::timeout, this, [this] { m_link_up ? pollNow() : connectNow(); });
}

DeviceWorker::~DeviceWorker() = default;

void DeviceWorker::start() {
    // The libmodbus context is made here, on the thread that will use it.
    m_module = std::make_unique<TemperatureModule>(m_map, m_url, m_options.response_timeout_s);
    m_backoff_s = m_options.backoff_initial_s;
    setHealth(DeviceHealth::Connecting);
    connectNow();
}

void DeviceWorker::shutdown() {
    m_stop = true;
    m_timer->stop();
    if (m_module) m_module->close();
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
    if (!m_module->connect(&error)) return failed(error);
    m_link_up = true;
    pollNow();
}

void DeviceWorker::pollNow() {
    if (m_stop) return;
    QString error;
    std::optional<TemperatureReading> reading = m_module->read(&error);
    if (!reading) return failed(error);
    if (m_outage && m_last_reading_utc.isValid()) emit gap(m_last_reading_utc, reading->time_utc);
    // The cycle ends with data, not with a connect: a device that accepts
    // TCP but never answers stays one cycle with one error.
    m_outage = false;
    m_error_reported = false;
    m_attempts = 0;
    m_backoff_s = m_options.backoff_initial_s;
    m_last_reading_utc = reading->time_utc;
    setHealth(DeviceHealth::Connected);
    emit readingReady(*reading);
    m_timer->start(toMs(m_options.poll_interval_s));
}

void DeviceWorker::failed(const QString& message) {
    m_module->close();
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

TemperatureDevice::TemperatureDevice(ChannelRegisterMap map, modbus::ModbusUrl url,
                                     DeviceWorkerOptions options, QObject* parent)
    : QObject(parent) {
    qRegisterMetaType<TemperatureReading>();
    qRegisterMetaType<DeviceHealth>();
    m_thread = new QThread;
    m_thread->setObjectName(QStringLiteral("device %1").arg(url.endpoint()));
    m_worker = new DeviceWorker(std::move(map), std::move(url), options);
    m_worker->moveToThread(m_thread);
    QObject::connect(m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    // Cross-thread, so these connections are queued: slots here run on our thread.
    QObject::connect(m_worker, &DeviceWorker::readingReady, this, &TemperatureDevice::readingReady);
    QObject::connect(m_worker, &DeviceWorker::errorOccurred, this,
                     &TemperatureDevice::errorOccurred);
    QObject::connect(m_worker, &DeviceWorker::gap, this, &TemperatureDevice::gap);
    QObject::connect(m_worker, &DeviceWorker::healthChanged, this,
                     &TemperatureDevice::healthChanged);
    QObject::connect(m_worker, &DeviceWorker::attemptFailed, this,
                     &TemperatureDevice::attemptFailed);
}

TemperatureDevice::~TemperatureDevice() {
    stopAndWait(kDefaultStopTimeoutMs);
    // Never started: the worker's deleteLater on finished will not come.
    if (m_thread && !m_started) delete m_worker;
    delete m_thread;  // null when stopAndWait handed it over
}

void TemperatureDevice::start() {
    // One run per device: after a stop the worker is deleted with its thread.
    if (!m_thread || m_started) return;
    m_started = true;
    m_thread->start();
    QMetaObject::invokeMethod(m_worker, &DeviceWorker::start, Qt::QueuedConnection);
}

bool TemperatureDevice::isRunning() const {
    return m_thread && m_thread->isRunning();
}

bool TemperatureDevice::stopAndWait(int timeout_ms) {
    if (!m_thread) return true;
    if (!m_thread->isRunning()) return true;
    m_worker->requestStop();
    // The worker quits its thread once it has closed the link.
    QMetaObject::invokeMethod(m_worker, &DeviceWorker::shutdown, Qt::QueuedConnection);
    if (m_thread->wait(QDeadlineTimer(timeout_ms))) return true;
    qCWarning(lcDevice) << "device thread still in a request after" << timeout_ms
                        << "ms; it will end on its own";
    // Hand the thread to itself: it deletes itself when it finishes.
    QObject::connect(m_thread, &QThread::finished, m_thread, &QObject::deleteLater);
    m_thread = nullptr;
    m_worker = nullptr;
    return false;
}

}  // namespace driftlab::devices
