#include "ui/pages/ModelsPage.h"

#include <QComboBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>
#include <cmath>

#include "ui/models/CrossStateMatrixModel.h"
#include "ui/models/ModelParametersModel.h"
#include "ui/models/TestScoresModel.h"
#include "ui/shell/BackgroundJob.h"
#include "ui/shell/FitJob.h"
#include "ui/shell/Session.h"
#include "ui/widgets/FitSetupPanel.h"
#include "ui/widgets/PredictionPlotWidget.h"
#include "ui/widgets/ResultTableView.h"

namespace driftlab::ui {
ModelsPage::ModelsPage(Session& session, QWidget* parent)
    : QWidget(parent), m_session(session), m_job(new BackgroundJob(this)) {
    m_setup = new FitSetupPanel(this);
    m_fit = new QPushButton(tr("&Fit"), this);
    m_fit->setToolTip(tr("Fit the model on the training runs and score it on the test runs"));
    m_compare = new QPushButton(tr("&Compare all models"), this);
    m_compare->setToolTip(
        tr("The cross-state matrix: every model fitted on each run and scored on every run"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_progress = new QProgressBar(this);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* controls = new QGroupBox(tr("Model"), this);
    auto* left = new QVBoxLayout(controls);
    left->addWidget(m_setup);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_fit);
    buttons->addWidget(m_cancel);
    left->addLayout(buttons);
    left->addWidget(m_compare);
    left->addWidget(m_progress);
    left->addWidget(m_status);
    left->addStretch();
    controls->setMaximumWidth(340);

    m_tabs = new QTabWidget(this);
    m_tabs->addTab(buildFitTab(), tr("Fit result"));
    m_predictions = new PredictionPlotWidget(this);
    m_tabs->addTab(m_predictions, tr("Predictions"));
    m_tabs->addTab(buildMatrixTab(), tr("Cross-state matrix"));

    auto* layout = new QHBoxLayout(this);
    layout->addWidget(controls);
    layout->addWidget(m_tabs, 1);

    connect(m_fit, &QPushButton::clicked, this, &ModelsPage::fit);
    connect(m_compare, &QPushButton::clicked, this, &ModelsPage::compare);
    connect(m_cancel, &QPushButton::clicked, this, &ModelsPage::cancel);
    connect(m_setup, &FitSetupPanel::changed, this, &ModelsPage::updateButtons);
    connect(m_job, &BackgroundJob::progressChanged, this, [this](double f) {
        m_progress->setRange(0, f < 0 ? 0 : 1000);  // a range of 0: busy, no fraction
        if (f >= 0) m_progress->setValue(int(std::lround(1000 * f)));
    });
    connect(&m_session, &Session::campaignSelected, this, &ModelsPage::reload);
    connect(&m_session, &Session::storeChanged, this, &ModelsPage::reload);
    setBusy(false);
    reload();
}

ModelsPage::~ModelsPage() = default;

QWidget* ModelsPage::buildFitTab() {
    auto* tab = new QWidget(this);
    m_fitSummary = new QLabel(tr("No fit yet."), tab);
    m_fitSummary->setWordWrap(true);
    m_notes = new QLabel(tab);
    m_notes->setWordWrap(true);
    m_notes->setTextFormat(Qt::RichText);
    m_parameters = new ModelParametersModel(this);
    m_scores = new TestScoresModel(this);
    auto* split = new QSplitter(Qt::Vertical, tab);
    split->addWidget(resultTableView(m_parameters, split));
    split->addWidget(resultTableView(m_scores, split));
    auto* layout = new QVBoxLayout(tab);
    layout->addWidget(m_fitSummary);
    layout->addWidget(split, 1);
    layout->addWidget(m_notes);
    return tab;
}

QWidget* ModelsPage::buildMatrixTab() {
    auto* tab = new QWidget(this);
    m_matrix = new CrossStateMatrixModel(this);
    m_matrixView = resultTableView(m_matrix, tab);
    m_matrixView->verticalHeader()->setVisible(true);
    m_matrixView->horizontalHeader()->setStretchLastSection(false);
    m_matrixView->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_matrixView->setSelectionMode(QAbstractItemView::NoSelection);
    m_matrixLegend = new QLabel(tr("Press \"Compare all models\" to fill the matrix."), tab);
    m_matrixLegend->setWordWrap(true);
    auto* layout = new QVBoxLayout(tab);
    auto* explanation = new QLabel(tr("RMS residual (µm) on each run (columns) of the model fitted "
                                      "on each run alone (rows). (…) on the diagonal: training "
                                      "score; off it: held-out scores. Green: lowest, red: "
                                      "highest (log scale)."),
                                   tab);
    explanation->setWordWrap(true);
    layout->addWidget(explanation);
    layout->addWidget(m_matrixView, 1);
    layout->addWidget(m_matrixLegend);
    return tab;
}

QString ModelsPage::status() const {
    return m_status->text();
}

QString ModelsPage::notes() const {
    return m_notes->text();
}

void ModelsPage::report(const QString& level, const QString& message) {
    m_status->setText(message);
    emit m_session.event(level, QStringLiteral("Models"), message);
}

void ModelsPage::setBusy(bool busy) {
    m_cancel->setEnabled(busy);
    m_setup->setEnabled(!busy);
    if (!busy) {
        m_progress->setRange(0, 1000);
        m_progress->setValue(m_progress->maximum());
    }
    updateButtons();
}

void ModelsPage::updateButtons() {
    const bool idle = !m_job->isRunning() && m_listsLoaded;
    m_fit->setEnabled(idle && !m_setup->trainRuns().isEmpty());
    m_compare->setEnabled(idle && m_setup->targetBox()->count() > 0);
}

void ModelsPage::reload() {
    m_listsLoaded = false;
    m_setup->clear();
    if (m_job->isRunning()) {
        // The running job belongs to the campaign before: stop it, reload after.
        m_reloadPending = true;
        m_job->cancel();
        return;
    }
    const QString path = m_session.storePath();
    const auto id = m_session.campaignId();
    if (path.isEmpty() || !id) {
        m_status->setText(tr("Select a campaign in the campaign tree."));
        updateButtons();
        return;
    }
    auto lists = std::make_shared<ModelledRunLists>();
    m_status->setText(tr("Reading the campaign …"));
    m_job->start([path, id, lists](JobControl&) { *lists = listModelledRuns(path, *id); },
                 [this, lists] {
                     if (reloadIfPending()) return;
                     if (!lists->error.isEmpty()) {
                         report(QStringLiteral("error"),
                                tr("Cannot read the campaign: %1").arg(lists->error));
                     } else {
                         m_listsLoaded = true;
                         m_setup->setRunLists(*lists);
                         m_status->setText(lists->targets.isEmpty()
                                               ? tr("This campaign has no run a model can use.")
                                               : tr("Ready."));
                     }
                     setBusy(false);
                 });
    setBusy(true);
}

bool ModelsPage::reloadIfPending() {
    // Called when a job has ended, before its result is shown: a result of the
    // campaign selected before is dropped.
    if (!m_reloadPending) return false;
    m_reloadPending = false;
    setBusy(false);
    reload();
    return true;
}

void ModelsPage::fit() {
    if (m_job->isRunning() || !m_session.campaignId()) return;
    FitRequest request{m_session.storePath(), *m_session.campaignId(), m_setup->model(),
                       m_setup->target(),     m_setup->trainRuns(),    m_setup->testRuns()};
    auto outcome = std::make_shared<FitOutcome>();
    m_status->setText(tr("Fitting %1 on %2 …").arg(request.model, request.train_runs.join(',')));
    m_job->start([request, outcome](JobControl& c) { *outcome = runFit(request, c); },
                 [this, outcome, model = request.model] {
                     if (reloadIfPending()) return;
                     setBusy(false);
                     showFit(*outcome, model);
                 });
    setBusy(true);
}

void ModelsPage::compare() {
    if (m_job->isRunning() || !m_session.campaignId()) return;
    const QString path = m_session.storePath(), target = m_setup->target();
    const qint64 id = *m_session.campaignId();
    auto outcome = std::make_shared<CompareOutcome>();
    m_status->setText(tr("Comparing every model on every run …"));
    m_job->start(
        [path, id, target, outcome](JobControl& c) { *outcome = runCompare(path, id, target, c); },
        [this, outcome] {
            if (reloadIfPending()) return;
            setBusy(false);
            showComparison(*outcome);
        });
    setBusy(true);
}

void ModelsPage::cancel() {
    m_job->cancel();
    m_status->setText(tr("Cancelling …"));
}

void ModelsPage::showFit(const FitOutcome& outcome, const QString& model) {
    if (outcome.cancelled) {
        report(QStringLiteral("info"), tr("Fit of %1 cancelled; nothing stored.").arg(model));
        return;
    }
    if (!outcome.error.isEmpty() && !outcome.fit_id) {
        report(QStringLiteral("error"), tr("Fit of %1 failed: %2").arg(model, outcome.error));
        return;
    }
    m_parameters->setParameters(outcome.fit.parameters);
    std::vector<TestScoresModel::Row> rows;
    for (const RunPrediction& run : outcome.runs) rows.push_back({run.run_id, run.score});
    if (outcome.runs.size() > 1) rows.push_back({tr("all test runs"), outcome.pooled});
    m_scores->setRows(std::move(rows));
    m_fitSummary->setText(
        tr("<b>%1</b> — training RMS %2 µm, %3 iterations. %4 score: RMS %5 µm, peak %6 µm, "
           "%7 % of the thermal error removed.")
            .arg(outcome.fit.message.toHtmlEscaped())
            .arg(outcome.fit.rms_um, 0, 'f', 2)
            .arg(outcome.fit.iterations)
            .arg(outcome.held_out ? tr("Held-out") : tr("Training (no run held out)"))
            .arg(outcome.pooled.rms_um, 0, 'f', 2)
            .arg(outcome.pooled.peak_um, 0, 'f', 2)
            .arg(100 * outcome.pooled.reduction, 0, 'f', 1));
    QStringList notes = outcome.fit.notes;
    if (!outcome.note.isEmpty()) notes << outcome.note;
    QStringList shown;
    // What the fit may be trusted with first: harm, the interval's coverage,
    // the holes of the log.
    if (outcome.held_out && outcome.pooled.reduction < 0)
        shown << tr("<b>The model makes the held-out runs' thermal error worse, not better:</b> "
                    "RMS %1 µm with it, %2 µm without. Do not compensate with it.")
                     .arg(outcome.pooled.rms_um, 0, 'f', 2)
                     .arg(outcome.pooled.uncompensated_rms_um, 0, 'f', 2);
    if (outcome.coverage.known())
        shown << tr("Prediction interval ±%1 µm (95 %)%2: %3 % of the held-out readings "
                    "inside it%4.")
                     .arg(outcome.validation.interval.half_width_um, 0, 'f', 2)
                     .arg(models::extrapolationWords(
                              outcome.validation.interval,
                              !outcome.beyond_training.empty() || !outcome.speeds_beyond.empty())
                              .toHtmlEscaped())
                     .arg(100 * outcome.coverage.share, 0, 'f', 0)
                     .arg(outcome.coverage.farBelowClaim()
                              ? tr(", far less than it claims: the held-out runs differ from "
                                   "the training runs more than these differ among themselves")
                              : QString());
    for (const QString& line : models::gapLines(outcome.gaps)) shown << line.toHtmlEscaped();
    if (!notes.isEmpty()) shown << tr("Notes: ") + notes.join(QStringLiteral("; ")).toHtmlEscaped();
    // On a line of its own: it qualifies the held-out score above.
    const QStringList beyond = models::describeRisesBeyondTraining(outcome.beyond_training);
    if (!beyond.isEmpty())
        shown << tr("Beyond the training runs' temperature rises (the prediction extrapolates "
                    "there): %1")
                     .arg(beyond.join(QStringLiteral("; ")).toHtmlEscaped());
    const QStringList faster = models::describeSpeedsBeyondTraining(outcome.speeds_beyond);
    if (!faster.isEmpty())
        shown << tr("Beyond the training runs' spindle speeds (the prediction extrapolates "
                    "there): %1")
                     .arg(faster.join(QStringLiteral("; ")).toHtmlEscaped());
    m_notes->setText(shown.join(QStringLiteral("<br>")));
    m_predictions->setPredictions(model, outcome.runs);
    if (outcome.fit_id) {
        // The log names what the fit did not see (flagged samples left out).
        report(QStringLiteral("info"),
               tr("Fitted %1: held-out RMS %2 µm; stored as fit %3.%4")
                   .arg(model)
                   .arg(outcome.pooled.rms_um, 0, 'f', 2)
                   .arg(*outcome.fit_id)
                   .arg(outcome.note.isEmpty() ? QString() : QStringLiteral(" ") + outcome.note));
        m_session.notifyStoreChanged();
    } else {
        report(QStringLiteral("error"),
               tr("Fitted %1 but not stored: %2").arg(model, outcome.error));
    }
    m_tabs->setCurrentIndex(0);
}

void ModelsPage::showComparison(const CompareOutcome& outcome) {
    if (outcome.cancelled) {
        report(QStringLiteral("info"), tr("Comparison cancelled."));
        return;
    }
    if (!outcome.error.isEmpty()) {
        report(QStringLiteral("error"), tr("Comparison failed: %1").arg(outcome.error));
        return;
    }
    m_matrix->setMatrices(outcome.runs, outcome.matrices);
    const QStringList errors = m_matrix->errors();
    m_matrixLegend->setText(
        tr("Scale: %1 µm (green) to %2 µm (red).")
            .arg(m_matrix->minimumRms(), 0, 'f', 2)
            .arg(m_matrix->maximumRms(), 0, 'f', 2) +
        (errors.isEmpty() ? QString() : QStringLiteral("\n") + errors.join(QLatin1Char('\n'))));
    m_tabs->setCurrentIndex(2);
    report(
        QStringLiteral("info"),
        tr("Compared %1 models on %2 runs.").arg(outcome.matrices.size()).arg(outcome.runs.size()));
}

}  // namespace driftlab::ui
