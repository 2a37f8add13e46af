#include "ui/shell/BackgroundJob.h"

#include <QtConcurrent/QtConcurrentRun>

namespace driftlab::ui {

BackgroundJob::BackgroundJob(QObject* parent) : QObject(parent) {
    // 10 Hz is smooth for a progress bar and costs the GUI thread nothing.
    m_progressTimer.setInterval(100);
    connect(&m_progressTimer, &QTimer::timeout, this, &BackgroundJob::reportProgress);
    connect(&m_watcher, &QFutureWatcher<void>::finished, this, &BackgroundJob::complete);
}

BackgroundJob::~BackgroundJob() {
    if (!m_running) return;
    m_control->cancel();
    m_watcher.disconnect(this);
    m_watcher.waitForFinished();
}

bool BackgroundJob::start(std::function<void(JobControl&)> work, std::function<void()> done) {
    if (m_running) return false;
    m_running = true;
    m_control = std::make_shared<JobControl>();
    m_done = std::move(done);
    std::shared_ptr<JobControl> control = m_control;
    m_watcher.setFuture(QtConcurrent::run([control, work = std::move(work)] { work(*control); }));
    m_progressTimer.start();
    emit progressChanged(0);
    return true;
}

void BackgroundJob::cancel() {
    if (m_running) m_control->cancel();
}

void BackgroundJob::reportProgress() {
    if (m_running) emit progressChanged(m_control->fraction());
}

void BackgroundJob::complete() {
    m_progressTimer.stop();
    m_running = false;
    if (m_done) std::exchange(m_done, nullptr)();
    emit finished();
}

}  // namespace driftlab::ui
