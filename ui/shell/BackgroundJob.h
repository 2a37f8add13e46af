#pragma once
// One long operation (a fit, a comparison, a diagnosis) on the thread pool,
// watched from the GUI thread: progress read from an atomic by a timer,
// Cancel through an atomic flag that core's progress callbacks and cancel
// checks read, and a completion callback back on the GUI thread.

#include <QFutureWatcher>
#include <QObject>
#include <QTimer>
#include <atomic>
#include <functional>
#include <memory>

namespace driftlab::ui {

/// What the worker and the GUI share. The worker reports; the GUI cancels.
class JobControl {
public:
    /// A fraction in [0, 1], or a negative value for "busy, no fraction".
    /// Returns false once cancelled: pass it as core's progress callback.
    bool progress(double fraction) {
        m_fraction.store(fraction);
        return !m_cancel.load();
    }
    bool cancelled() const { return m_cancel.load(); }
    void cancel() { m_cancel.store(true); }
    double fraction() const { return m_fraction.load(); }

private:
    std::atomic<bool> m_cancel{false};
    std::atomic<double> m_fraction{0};
};

class BackgroundJob : public QObject {
    Q_OBJECT
public:
    explicit BackgroundJob(QObject* parent = nullptr);
    /// Cancels a running job and waits for it (the work checks the flag often).
    ~BackgroundJob() override;

    bool isRunning() const { return m_running; }
    /// Runs `work` on the thread pool; `done` runs on the GUI thread when it
    /// has returned, before finished(). Refused (false) while a job runs.
    bool start(std::function<void(JobControl&)> work, std::function<void()> done);

public slots:
    void cancel();

signals:
    void progressChanged(double fraction);
    void finished();

private:
    void reportProgress();
    void complete();

    QFutureWatcher<void> m_watcher;
    QTimer m_progressTimer;
    std::shared_ptr<JobControl> m_control;
    std::function<void()> m_done;
    bool m_running = false;
};

}  // namespace driftlab::ui
