#pragma once
// The Run page (DESIGN.md section 9): the pre-run checklist, run control on
// the procedure engine, and the live dashboard. Its run-control actions go
// into the main window's tool bar, its state widget into the status bar.

#include <QList>
#include <QWidget>

class QAction;

namespace driftlab::ui {

class Session;

class RunPage : public QWidget {
    Q_OBJECT
public:
    explicit RunPage(Session& session, QWidget* parent = nullptr);

    /// Start, pause, resume, abort (with their shortcuts).
    QList<QAction*> runActions() const { return m_actions; }
    /// Run state, elapsed and next-measurement time, one health light per device.
    QWidget* statusWidget() const { return m_status; }

private:
    Session& m_session;
    QList<QAction*> m_actions;
    QWidget* m_status = nullptr;
};

}  // namespace driftlab::ui
