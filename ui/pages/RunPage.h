#pragma once
// The Run page (docs/gui-run.md): the pre-run checklist, run control on
// the procedure engine (RunController), state and progress, and the live
// dashboard. Its run-control actions go into the main window's tool bar, its
// state widget into the status bar.

#include <QList>
#include <QWidget>

class QAction;
class QLabel;
class QProgressBar;

namespace driftlab::ui {

class Session;
class RunController;
class PreRunChecklist;
class LiveDashboard;
class RunStatusWidget;

class RunPage : public QWidget {
    Q_OBJECT
public:
    explicit RunPage(Session& session, QWidget* parent = nullptr);
    ~RunPage() override;

    /// Start (F5), pause and resume (F6), abort (Shift+F5).
    QList<QAction*> runActions() const { return m_actions; }
    QAction* startAction() const { return m_start; }
    QAction* pauseAction() const { return m_pause; }
    QAction* resumeAction() const { return m_resume; }
    QAction* abortAction() const { return m_abort; }
    /// Run state, elapsed and next-measurement time, one health light per device.
    QWidget* statusWidget() const;
    RunController& controller() const { return *m_controller; }
    PreRunChecklist& checklist() const { return *m_checklist; }
    LiveDashboard& dashboard() const { return *m_dashboard; }
    /// The progress line as shown ("run 1 of 5 …").
    QString progressText() const;

private:
    void startWhenChecked(bool passed);
    void updateActions();
    void showProgress();

    Session& m_session;
    RunController* m_controller;
    PreRunChecklist* m_checklist;
    LiveDashboard* m_dashboard;
    RunStatusWidget* m_status;
    QLabel* m_stateLabel;
    QLabel* m_progressLabel;
    QLabel* m_message;
    QProgressBar* m_progressBar;
    QAction *m_start, *m_pause, *m_resume, *m_abort;
    QList<QAction*> m_actions;
    bool m_startRequested = false;
};

}  // namespace driftlab::ui
