#include "acquisition/devices/DeviceThread.h"

#include <QLoggingCategory>
#include <QThread>

namespace driftlab::devices {

Q_DECLARE_LOGGING_CATEGORY(lcDevice)

DeviceThread::DeviceThread(PolledDeviceFactory make_device, const QString& name,
                           DeviceWorkerOptions options, QObject* parent)
    : QObject(parent) {
    qRegisterMetaType<DeviceHealth>();
    m_thread = new QThread;
    m_thread->setObjectName(name);
    m_worker = new DeviceWorker(std::move(make_device), options);
    m_worker->moveToThread(m_thread);
    QObject::connect(m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    // Cross-thread, so these connections are queued: slots here run on our thread.
    QObject::connect(m_worker, &DeviceWorker::readingReady, this, &DeviceThread::readingReady);
    QObject::connect(m_worker, &DeviceWorker::errorOccurred, this, &DeviceThread::errorOccurred);
    QObject::connect(m_worker, &DeviceWorker::gap, this, &DeviceThread::gap);
    QObject::connect(m_worker, &DeviceWorker::healthChanged, this, &DeviceThread::healthChanged);
    QObject::connect(m_worker, &DeviceWorker::attemptFailed, this, &DeviceThread::attemptFailed);
}

DeviceThread::~DeviceThread() {
    stopAndWait(kDefaultStopTimeoutMs);
    // Never started: the worker's deleteLater on finished will not come.
    if (m_thread && !m_started) delete m_worker;
    delete m_thread;  // null when stopAndWait handed it over
}

void DeviceThread::start() {
    // One run per device: after a stop the worker is deleted with its thread.
    if (!m_thread || m_started) return;
    m_started = true;
    m_thread->start();
    QMetaObject::invokeMethod(m_worker, &DeviceWorker::start, Qt::QueuedConnection);
}

bool DeviceThread::isRunning() const {
    return m_thread && m_thread->isRunning();
}

bool DeviceThread::stopAndWait(int timeout_ms) {
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
