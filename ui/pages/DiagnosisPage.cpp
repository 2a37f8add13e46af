#include "ui/pages/DiagnosisPage.h"

#include <QComboBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>
#include <cmath>

#include "db/DiagnosisRecords.h"
#include "ui/models/FindingsModel.h"
#include "ui/models/StoredDiagnosesModel.h"
#include "ui/plots/DiagnosisPlots.h"
#include "ui/shell/BackgroundJob.h"
#include "ui/shell/DiagnosisJob.h"
#include "ui/shell/Session.h"
#include "ui/widgets/PlotView.h"
#include "ui/widgets/ResultTableView.h"

namespace driftlab::ui {
DiagnosisPage::DiagnosisPage(Session& session, QWidget* parent)
    : QWidget(parent), m_session(session), m_job(new BackgroundJob(this)) {
    m_diagnose = new QPushButton(tr("&Diagnose"), this);
    m_diagnose->setToolTip(
        tr("Fit the heat-transfer model, refit it with every candidate effect "
           "and name the cause the held-out runs confirm"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1000);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    m_verdict = new QLabel(tr("No diagnosis yet."), this);
    m_verdict->setWordWrap(true);
    m_verdict->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_findings = new FindingsModel(this);
    m_findingsView = resultTableView(m_findings, this);
    m_findingsView->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_adopt = new QPushButton(tr("&Adopt the selected extension"), this);
    m_adopt->setToolTip(tr("Keep the extended model as a model fit of the campaign"));
    m_stored = new StoredDiagnosesModel(this);
    auto* storedView = resultTableView(m_stored, this);

    m_run = new QComboBox(this);
    m_map = new PlotView(this);
    m_curves = new PlotView(this);
    m_map->showMessage(tr("The residual map of each held-out run appears here."));
    m_curves->showMessage(tr("The thermal error before and after the extension appears here."));

    auto* top = new QHBoxLayout;
    top->addWidget(m_diagnose);
    top->addWidget(m_cancel);
    top->addWidget(m_progress, 1);
    top->addWidget(m_status, 2);

    auto* findingsBox = new QGroupBox(tr("Findings (bold: the verdict)"), this);
    auto* findingsLayout = new QVBoxLayout(findingsBox);
    findingsLayout->addWidget(m_findingsView, 1);
    findingsLayout->addWidget(m_adopt);
    auto* storedBox = new QGroupBox(tr("Stored diagnoses of this campaign"), this);
    auto* storedLayout = new QVBoxLayout(storedBox);
    storedLayout->addWidget(storedView);
    auto* leftSplit = new QSplitter(Qt::Vertical, this);
    leftSplit->addWidget(findingsBox);
    leftSplit->addWidget(storedBox);
    leftSplit->setStretchFactor(0, 3);
    leftSplit->setStretchFactor(1, 1);

    auto* plots = new QWidget(this);
    auto* plotLayout = new QVBoxLayout(plots);
    plotLayout->setContentsMargins(0, 0, 0, 0);
    auto* runRow = new QHBoxLayout;
    runRow->addWidget(new QLabel(tr("Held-out run"), plots));
    runRow->addWidget(m_run);
    runRow->addStretch();
    plotLayout->addLayout(runRow);
    plotLayout->addWidget(m_map, 1);
    plotLayout->addWidget(m_curves, 1);

    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(leftSplit);
    split->addWidget(plots);
    // The plots need the room: residual map and curves over hours.
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_verdict);
    layout->addWidget(split, 1);

    connect(m_diagnose, &QPushButton::clicked, this, &DiagnosisPage::diagnose);
    connect(m_cancel, &QPushButton::clicked, this, &DiagnosisPage::cancel);
    connect(m_adopt, &QPushButton::clicked, this, &DiagnosisPage::adopt);
    connect(m_run, &QComboBox::currentIndexChanged, this, &DiagnosisPage::drawPlots);
    connect(m_findingsView->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            [this] { setBusy(m_job->isRunning()); });
    connect(m_job, &BackgroundJob::progressChanged, this,
            [this](double f) { m_progress->setValue(int(std::lround(1000 * std::max(0.0, f)))); });
    connect(&m_session, &Session::campaignSelected, this, &DiagnosisPage::campaignChanged);
    connect(&m_session, &Session::storeChanged, this, &DiagnosisPage::campaignChanged);
    connect(&m_session, &Session::storeContentChanged, this, &DiagnosisPage::refreshStored);
    campaignChanged();
}

DiagnosisPage::~DiagnosisPage() = default;

QString DiagnosisPage::status() const {
    return m_status->text();
}

QString DiagnosisPage::verdict() const {
    return m_outcome ? m_outcome->result.verdict : QString();
}

void DiagnosisPage::report(const QString& level, const QString& message) {
    m_status->setText(message);
    emit m_session.event(level, QStringLiteral("Diagnosis"), message);
}

void DiagnosisPage::setBusy(bool busy) {
    const bool campaign = m_session.campaignId().has_value();
    m_diagnose->setEnabled(!busy && campaign);
    m_cancel->setEnabled(busy);
    if (!busy) m_progress->setValue(m_progress->maximum());
    const QModelIndexList rows = m_findingsView->selectionModel()->selectedRows();
    m_adopt->setEnabled(!busy && m_outcome && m_outcome->diagnosis_id && !rows.isEmpty() &&
                        m_adoptedFinding != rows.front().row());
}

void DiagnosisPage::campaignChanged() {
    m_job->cancel();  // a diagnosis of the campaign before is of no use now
    m_outcome.reset();
    m_adoptedFinding.reset();
    m_findings->setFindings({}, {});
    m_run->clear();
    m_verdict->setText(tr("No diagnosis yet."));
    refreshStored();
    setBusy(m_job->isRunning());
}

void DiagnosisPage::refreshStored() {
    std::vector<db::DiagnosisRecord> records;
    if (!m_session.storePath().isEmpty() && m_session.campaignId()) {
        QString error;
        // A few small rows: read on the GUI thread with a connection of its own.
        if (auto store =
                db::CampaignStore::open(m_session.storePath(), db::StoreAccess::ReadOnly, &error))
            records = db::diagnoses(*store, *m_session.campaignId());
        else
            report(QStringLiteral("error"), tr("Cannot read stored diagnoses: %1").arg(error));
    }
    m_stored->setDiagnoses(std::move(records));
}

void DiagnosisPage::diagnose() {
    if (m_job->isRunning() || !m_session.campaignId()) return;
    const QString path = m_session.storePath();
    const qint64 id = *m_session.campaignId();
    auto outcome = std::make_shared<DiagnosisOutcome>();
    m_status->setText(tr("Diagnosing: the base model, then every candidate effect …"));
    m_job->start([path, id, outcome](JobControl& c) { *outcome = runDiagnosis(path, id, c); },
                 [this, outcome, id] {
                     setBusy(false);
                     if (m_session.campaignId() == id) show(*outcome);
                 });
    setBusy(true);
}

void DiagnosisPage::cancel() {
    m_job->cancel();
    m_status->setText(tr("Cancelling …"));
}

void DiagnosisPage::show(const DiagnosisOutcome& outcome) {
    if (outcome.cancelled) {
        report(QStringLiteral("info"), tr("Diagnosis cancelled; nothing stored."));
        return;
    }
    if (!outcome.error.isEmpty() && !outcome.diagnosis_id) {
        report(QStringLiteral("error"), tr("Diagnosis failed: %1").arg(outcome.error));
        return;
    }
    m_outcome = std::make_shared<const DiagnosisOutcome>(outcome);
    m_adoptedFinding.reset();
    const diagnosis::DiagnosisResult& r = m_outcome->result;
    const diagnosis::Finding* named = diagnosis::verdictFinding(r);
    const diagnosis::Finding* first =
        r.causes.isEmpty() ? nullptr : diagnosis::adoptedFinding(r, r.causes.front());
    m_verdict->setText(
        tr("<b>Verdict: %1</b>%2 — trained on %3, held out %4. Base model on the held-out runs: "
           "%5 µm RMS (reading noise %6 µm).<br>%7")
            .arg(r.verdict.toHtmlEscaped(),
                 first ? tr(" (confidence %1)").arg(first->confidence, 0, 'f', 2) : QString(),
                 r.train_runs.join(','), r.test_runs.join(','))
            .arg(r.base_test.error_rms_um, 0, 'f', 2)
            .arg(r.base_test.error_noise_um, 0, 'f', 2)
            .arg((named
                      ? named->evidence +
                            (r.causes.size() > 1 ? tr(" Causes in order: %1.")
                                                       .arg(r.causes.join(QStringLiteral(", ")))
                                                 : QString()) +
                            (r.remaining.isEmpty() ? QString() : QStringLiteral(" ") + r.remaining)
                      : r.verdict_evidence)
                     .toHtmlEscaped()) +
        // The holes of the log the diagnosis bridged or left out, said as `diagnose` says them.
        [&] {
            QString lines;
            for (const QString& line : models::gapLines(r.gaps))
                lines += QStringLiteral("<br>") + line.toHtmlEscaped();
            return lines;
        }());
    m_findings->setFindings(r.findings, r.verdict);
    if (m_findings->verdictRow() >= 0) m_findingsView->selectRow(m_findings->verdictRow());
    {
        const QSignalBlocker blocker(m_run);
        m_run->clear();
        for (const auto& residuals : r.base_residuals) m_run->addItem(residuals.run_id);
    }
    drawPlots();
    refreshStored();
    m_session.notifyStoreChanged();
    report(QStringLiteral("info"), m_outcome->diagnosis_id
                                       ? tr("Diagnosis stored (id %1): verdict %2.")
                                             .arg(*m_outcome->diagnosis_id)
                                             .arg(r.verdict)
                                       : tr("Diagnosis not stored: %1").arg(outcome.error));
    setBusy(false);
}

void DiagnosisPage::drawPlots() {
    const int k = m_run->currentIndex();
    if (!m_outcome || k < 0 || k >= int(m_outcome->result.base_residuals.size()) ||
        k >= int(m_outcome->test_runs.size()))
        return;
    const diagnosis::DiagnosisResult& r = m_outcome->result;
    const auto& base = r.base_residuals[std::size_t(k)];
    m_map->showMap(
        residualMapPlot(base, tr("%1: positioning residual of the base model").arg(base.run_id)));
    const auto* adopted = diagnosis::adoptedResiduals(r, std::size_t(k));
    m_curves->showCurves(beforeAfterPlot(m_outcome->test_runs[std::size_t(k)], base, adopted,
                                         tr("with %1").arg(r.verdict),
                                         tr("%1: verdict %2").arg(base.run_id, r.verdict)));
}

void DiagnosisPage::adopt() {
    const QModelIndexList rows = m_findingsView->selectionModel()->selectedRows();
    if (!m_outcome || rows.isEmpty() || !m_session.campaignId()) return;
    const diagnosis::Finding* finding = m_findings->finding(rows.front().row());
    if (!finding) return;
    QString error;
    auto store = db::CampaignStore::open(m_session.storePath(), db::StoreAccess::ReadWrite, &error);
    const auto fitId = store
                           ? db::adoptExtension(*store, *m_session.campaignId(), m_outcome->result,
                                                *finding, m_outcome->diagnosis_id, &error)
                           : std::nullopt;
    if (!fitId) {
        report(QStringLiteral("error"), tr("Cannot adopt '%1': %2").arg(finding->cause, error));
        return;
    }
    store.reset();
    m_adoptedFinding = rows.front().row();
    report(QStringLiteral("info"),
           tr("Adopted heat-transfer+%1: stored as fit %2.").arg(finding->cause).arg(*fitId));
    m_session.notifyStoreChanged();
    setBusy(false);
}

}  // namespace driftlab::ui
