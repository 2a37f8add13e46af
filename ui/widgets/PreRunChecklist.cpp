#include "ui/widgets/PreRunChecklist.h"

#include <QFileInfo>
#include <QListWidget>
#include <QVBoxLayout>
#include <QtConcurrent>

#include "core/procedures/ProcedurePlan.h"
#include "ui/shell/RunController.h"
#include "ui/shell/Session.h"

namespace driftlab::ui {
namespace {

/// The procedure as the engine will get it: re-read from its file when it
/// came from one, parsed from its JSON otherwise, then planned.
QString procedureProblem(const RunSetup& setup) {
    QString why;
    std::optional<procedures::Procedure> procedure =
        setup.procedure_path.isEmpty()
            ? procedures::parseProcedure(procedures::toJson(setup.procedure), &why)
            : procedures::loadProcedureFile(setup.procedure_path, &why);
    if (!procedure) return why;
    try {
        const auto runs = procedures::planRuns(*procedure);
        if (runs.empty()) return QObject::tr("it plans no runs");
    } catch (const std::exception& e) {
        return QString::fromUtf8(e.what());
    }
    return {};
}

}  // namespace

PreRunChecklist::PreRunChecklist(Session& session, QWidget* parent)
    : QWidget(parent), m_session(session), m_list(new QListWidget(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_list);
    m_list->setWordWrap(true);
    m_list->setSelectionMode(QAbstractItemView::NoSelection);
    connect(&m_probe, &QFutureWatcher<std::vector<engine::DeviceProbeResult>>::finished, this,
            &PreRunChecklist::probesDone);
}

QStringList PreRunChecklist::lines() const {
    QStringList out;
    for (int i = 0; i < m_list->count(); ++i) out << m_list->item(i)->text();
    return out;
}

void PreRunChecklist::addLine(bool ok, const QString& text) {
    auto* item = new QListWidgetItem(
        style()->standardIcon(ok ? QStyle::SP_DialogApplyButton : QStyle::SP_MessageBoxCritical),
        text, m_list);
    item->setToolTip(text);
    if (!ok) m_problems << text;
}

void PreRunChecklist::check() {
    if (busy()) return;
    m_list->clear();
    m_problems.clear();
    m_checked = false;
    const RunSetup& setup = m_session.runSetup();
    const QString name = setup.procedure.name.isEmpty() ? tr("(unnamed)") : setup.procedure.name;
    const QString procedure = procedureProblem(setup);
    addLine(procedure.isEmpty(), procedure.isEmpty()
                                     ? tr("Procedure '%1' is valid").arg(name)
                                     : tr("Procedure '%1' is not valid: %2").arg(name, procedure));
    const QString store = m_session.storePath();
    addLine(!store.isEmpty(), store.isEmpty() ? tr("Store: none open (File ▸ New or Open)")
                                              : tr("Store %1").arg(QFileInfo(store).fileName()));
    if (setup.rig == QLatin1String("sim")) {
        const bool ok = setup.speedup >= 0;
        addLine(ok, setup.speedup > 0 ? tr("Simulated rig at %1× speed-up").arg(setup.speedup)
                    : ok              ? tr("Simulated rig as fast as it computes")
                         : tr("Simulated rig: speed-up %1 is negative").arg(setup.speedup));
        m_checked = true;
        emit checked(passed());
        return;
    }
    auto* pending = new QListWidgetItem(tr("Devices: asking each for one reading…"), m_list);
    pending->setData(Qt::UserRole, QStringLiteral("pending"));
    m_probing = true;
    m_probe.setFuture(QtConcurrent::run(
        [options = rigOptionsOf(setup)] { return engine::probeDevices(options, {}, 1.0); }));
}

void PreRunChecklist::probesDone() {
    m_probing = false;
    for (int i = m_list->count() - 1; i >= 0; --i)
        if (m_list->item(i)->data(Qt::UserRole).toString() == QLatin1String("pending"))
            delete m_list->takeItem(i);
    for (const engine::DeviceProbeResult& r : m_probe.result())
        addLine(r.ok, tr("%1: %2").arg(r.device, r.message));
    m_checked = true;
    emit checked(passed());
}

}  // namespace driftlab::ui
