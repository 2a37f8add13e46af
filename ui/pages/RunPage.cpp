#include "ui/pages/RunPage.h"

#include <QAction>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

#include "ui/shell/RunController.h"
#include "ui/shell/Session.h"
#include "ui/widgets/LiveDashboard.h"
#include "ui/widgets/PreRunChecklist.h"
#include "ui/widgets/RunStatusWidget.h"

namespace driftlab::ui {

using engine::EngineState;

RunPage::RunPage(Session& session, QWidget* parent)
    : QWidget(parent),
      m_session(session),
      m_controller(new RunController(session, this)),
      m_checklist(new PreRunChecklist(session, this)),
      m_dashboard(new LiveDashboard(this)),
      m_status(new RunStatusWidget(*m_controller->health())),
      m_stateLabel(new QLabel(this)),
      m_progressLabel(new QLabel(this)),
      m_message(new QLabel(this)),
      m_progressBar(new QProgressBar(this)) {
    auto action = [this](const QString& text, const QKeySequence& key, const QString& tip) {
        auto* a = new QAction(text, this);
        a->setShortcut(key);
        a->setShortcutContext(Qt::ApplicationShortcut);
        a->setToolTip(QStringLiteral("%1 (%2)").arg(tip, key.toString(QKeySequence::NativeText)));
        m_actions << a;
        return a;
    };
    m_start = action(tr("Start"), Qt::Key_F5, tr("Check, then start the procedure"));
    // Pause and resume share F6: only one of them is enabled at a time.
    m_pause = action(tr("Pause"), Qt::Key_F6, tr("Pause the run (its clock stops)"));
    m_resume = action(tr("Resume"), Qt::Key_F6, tr("Resume the paused run"));
    m_abort = action(tr("Abort"), QKeySequence(Qt::SHIFT | Qt::Key_F5),
                     tr("Abort: keep what was logged, mark the run interrupted"));
    connect(m_start, &QAction::triggered, this, [this] {
        m_startRequested = true;
        m_message->clear();
        m_checklist->check();
        updateActions();
    });
    connect(m_pause, &QAction::triggered, m_controller, &RunController::pause);
    connect(m_resume, &QAction::triggered, m_controller, &RunController::resume);
    connect(m_abort, &QAction::triggered, m_controller, &RunController::abort);
    connect(m_checklist, &PreRunChecklist::checked, this, &RunPage::startWhenChecked);
    connect(m_controller, &RunController::stateChanged, this, [this] {
        updateActions();
        showProgress();
    });
    connect(m_controller, &RunController::progressChanged, this, &RunPage::showProgress);
    connect(m_controller, &RunController::runStarted, this,
            [this] { m_dashboard->setTemperatureColumns(m_controller->temperatureColumns()); });
    connect(m_controller, &RunController::finished, this, [this](bool ok) {
        m_dashboard->refresh(true);
        m_dashboard->setLive(false);
        m_message->setText(ok ? tr("The run finished; the campaign is selected.")
                              : tr("The run ended early: see the event log."));
        updateActions();
    });
    m_dashboard->setSources([this] {
        return LiveSources{m_controller->liveBuffer(), m_controller->liveReadings()};
    });

    // Left: checklist and run state; right: the dashboard.
    auto* side = new QVBoxLayout;
    auto* checks = new QGroupBox(tr("Pre-run checklist"), this);
    auto* checksLayout = new QVBoxLayout(checks);
    checksLayout->addWidget(m_checklist);
    auto* recheck = new QPushButton(tr("Check now"), checks);
    connect(recheck, &QPushButton::clicked, m_checklist, &PreRunChecklist::check);
    checksLayout->addWidget(recheck);
    side->addWidget(checks, 1);
    auto* runBox = new QGroupBox(tr("Run"), this);
    auto* runLayout = new QVBoxLayout(runBox);
    auto* buttons = new QHBoxLayout;
    for (QAction* a : m_actions) {
        auto* b = new QToolButton(runBox);
        b->setDefaultAction(a);
        buttons->addWidget(b);
    }
    runLayout->addLayout(buttons);
    for (QWidget* w : {static_cast<QWidget*>(m_stateLabel), static_cast<QWidget*>(m_progressBar),
                       static_cast<QWidget*>(m_progressLabel), static_cast<QWidget*>(m_message)})
        runLayout->addWidget(w);
    m_message->setWordWrap(true);
    m_progressLabel->setWordWrap(true);
    side->addWidget(runBox);
    auto* layout = new QHBoxLayout(this);
    auto* sideWidget = new QWidget(this);
    sideWidget->setLayout(side);
    sideWidget->setMaximumWidth(340);
    layout->addWidget(sideWidget);
    layout->addWidget(m_dashboard, 1);

    connect(&m_session, &Session::runSetupChanged, m_checklist, &PreRunChecklist::check);
    connect(&m_session, &Session::storeChanged, m_checklist, &PreRunChecklist::check);
    updateActions();
    showProgress();
}

RunPage::~RunPage() {
    delete m_status;  // in the status bar, not our child
}

QWidget* RunPage::statusWidget() const {
    return m_status;
}

void RunPage::startWhenChecked(bool passed) {
    if (!m_startRequested) return;
    m_startRequested = false;
    if (!passed) {
        const QString why = m_checklist->problems().join(QStringLiteral("; "));
        m_message->setText(tr("Not started: %1").arg(why));
        emit m_session.event(QStringLiteral("error"), QStringLiteral("run"),
                             tr("not started: %1").arg(why));
        updateActions();
        return;
    }
    QString error;
    if (!m_controller->start(&error)) {
        m_message->setText(tr("Not started: %1").arg(error));
        emit m_session.event(QStringLiteral("error"), QStringLiteral("run"),
                             tr("not started: %1").arg(error));
    } else {
        m_dashboard->setTemperatureColumns(m_controller->temperatureColumns());
        m_dashboard->setLive(true);
    }
    updateActions();
}

void RunPage::updateActions() {
    const bool active = m_controller->active();
    const EngineState s = m_controller->state();
    m_start->setEnabled(!active && !m_startRequested && !m_checklist->busy());
    m_pause->setEnabled(active && s == EngineState::Running);
    m_resume->setEnabled(active && s == EngineState::Paused);
    m_abort->setEnabled(active && s != EngineState::Aborting);
}

QString RunPage::progressText() const {
    return m_progressLabel->text();
}

void RunPage::showProgress() {
    const engine::EngineProgress p = m_controller->progress();
    const auto next = m_controller->nextMeasurement_s();
    m_stateLabel->setText(tr("State: <b>%1</b>").arg(toString(m_controller->state())));
    m_progressBar->setRange(0, 1000);
    m_progressBar->setValue(p.duration_s > 0 ? int(1000 * std::min(1.0, p.time_s / p.duration_s))
                                             : 0);
    m_progressLabel->setText(
        p.run.isEmpty() ? tr("No run in progress")
                        : tr("Run %1 of %2 (%3): %4 / %5\n%6")
                              .arg(p.run_index + 1)
                              .arg(p.run_count)
                              .arg(p.run, clockText(p.time_s), clockText(p.duration_s),
                                   next ? tr("Next measurement at %1 (in %2)")
                                              .arg(clockText(*next), clockText(*next - p.time_s))
                                        : tr("No measurement due in this run")));
    m_status->showRun(m_controller->state(), m_controller->elapsed_s(), next);
}

}  // namespace driftlab::ui
