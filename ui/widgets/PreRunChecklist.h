#pragma once
// The pre-run checklist of the Run page: the procedure is valid (parsed and
// planned), a store is open, and the rig is ready — on a Modbus rig each
// device answers one read and its first temperatures are plausible (probed on
// a worker thread with a short timeout, never on the GUI thread); on the
// simulated rig, the speed-up. Each line says what was checked or why it fails.

#include <QFutureWatcher>
#include <QWidget>
#include <vector>

#include "acquisition/engine/DeviceProbe.h"

class QListWidget;

namespace driftlab::ui {

class Session;

class PreRunChecklist : public QWidget {
    Q_OBJECT
public:
    explicit PreRunChecklist(Session& session, QWidget* parent = nullptr);

    /// Runs every check; the device probes finish later (checked()).
    void check();
    /// Until the probes' results are shown: the worker may have finished
    /// while its finished() still waits in the GUI thread's event queue.
    bool busy() const { return m_probing; }
    bool passed() const { return !busy() && m_problems.isEmpty() && m_checked; }
    /// What failed, one line each, naming the check.
    QStringList problems() const { return m_problems; }
    /// The checklist's lines as shown (for tests and tooltips).
    QStringList lines() const;

signals:
    void checked(bool passed);

private:
    void addLine(bool ok, const QString& text);
    void probesDone();

    Session& m_session;
    QListWidget* m_list;
    QFutureWatcher<std::vector<engine::DeviceProbeResult>> m_probe;
    QStringList m_problems;
    bool m_checked = false;
    bool m_probing = false;
};

}  // namespace driftlab::ui
