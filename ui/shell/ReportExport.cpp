#include "ui/shell/ReportExport.h"

#include <QDateTime>
#include <QProgressDialog>
#include <QTimer>

#include "ui/report/ReportPdf.h"
#include "ui/shell/BackgroundJob.h"
#include "ui/shell/FitJob.h"
#include "ui/shell/Session.h"

namespace driftlab::ui {
namespace {

/// The progress bar's steps: the analysis, then the pages.
constexpr int kSteps = 1000;
constexpr double kAnalysisShare = 0.9;

struct ReportOutcome {
    QString error;
    QString note;
    driftlab::report::AcceptanceReportData data;
};

}  // namespace

ReportExport::ReportExport(Session& session, QWidget* dialogParent)
    : QObject(dialogParent),
      m_session(session),
      m_job(new BackgroundJob(this)),
      m_dialog(new QProgressDialog(dialogParent)) {
    m_dialog->setWindowTitle(tr("Export report"));
    m_dialog->setRange(0, kSteps);
    m_dialog->setAutoClose(false);
    m_dialog->setAutoReset(false);
    m_dialog->setMinimumDuration(0);
    m_dialog->setWindowModality(Qt::WindowModal);
    m_dialog->reset();
    m_dialog->hide();
    connect(m_dialog, &QProgressDialog::canceled, this, &ReportExport::cancel);
    connect(m_job, &BackgroundJob::progressChanged, this, [this](double f) {
        if (f >= 0) m_dialog->setValue(int(kSteps * kAnalysisShare * f));
    });
}

ReportExport::~ReportExport() = default;

bool ReportExport::isRunning() const {
    return m_job->isRunning() || m_pdf;
}

bool ReportExport::start(const QString& pdfPath) {
    const auto campaignId = m_session.campaignId();
    if (!campaignId || isRunning()) return false;
    m_path = pdfPath;
    m_cancelled = false;
    m_dialog->setLabelText(tr("Analysing the campaign (models, diagnosis)…"));
    m_dialog->setValue(0);
    m_dialog->show();
    const QString store = m_session.storePath();
    const qint64 id = *campaignId;
    auto outcome = std::make_shared<ReportOutcome>();
    driftlab::report::ReportOptions options;
    options.version = QStringLiteral(DRIFTLAB_VERSION);
    options.report_date =
        QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyy-MM-dd HH:mm 'UTC'"));
    m_job->start(
        [store, id, outcome, options](JobControl& control) mutable {
            // A connection of its own: a QSqlDatabase belongs to its thread.
            auto campaign = loadCampaignForModels(store, id, &outcome->note, &outcome->error);
            if (!campaign) return;
            options.progress = [&control](double f) { return control.progress(f); };
            outcome->data = driftlab::report::buildReportData(*campaign, options);
        },
        [this, outcome] {
            if (m_cancelled || outcome->data.cancelled) return finish(false, tr("cancelled"));
            if (!outcome->error.isEmpty()) return finish(false, outcome->error);
            if (!outcome->data.error.isEmpty()) return finish(false, outcome->data.error);
            render(outcome->data);
        });
    return true;
}

void ReportExport::cancel() {
    m_cancelled = true;
    m_job->cancel();
}

void ReportExport::render(const driftlab::report::AcceptanceReportData& data) {
    m_dialog->setLabelText(tr("Writing %1…").arg(m_path));
    m_pdf = std::make_unique<report::PdfRendering>(report::reportDocument(data), m_path);
    if (!m_pdf->error().isEmpty()) {
        const QString error = m_pdf->error();
        m_pdf.reset();
        return finish(false, error);
    }
    QTimer::singleShot(0, this, &ReportExport::drawNextPage);
}

void ReportExport::drawNextPage() {
    if (!m_pdf) return;
    if (m_cancelled) {
        m_pdf.reset();  // discards the file
        return finish(false, tr("cancelled"));
    }
    if (m_pdf->drawNextPage()) {
        const double f = double(m_pdf->pagesDrawn()) / m_pdf->pageCount();
        m_dialog->setValue(int(kSteps * (kAnalysisShare + (1 - kAnalysisShare) * f)));
        QTimer::singleShot(0, this, &ReportExport::drawNextPage);
        return;
    }
    const report::PdfResult r = m_pdf->finish();
    m_pdf.reset();
    if (!r.ok()) return finish(false, r.error);
    finish(true, tr("%1: %2 pages").arg(m_path).arg(r.pages));
}

void ReportExport::finish(bool written, const QString& message) {
    m_dialog->reset();
    m_dialog->hide();
    emit m_session.event(written ? QStringLiteral("info") : QStringLiteral("warning"),
                         QStringLiteral("report"),
                         written ? tr("report written: %1").arg(message)
                                 : tr("report not written: %1").arg(message));
    emit finished(written, message);
}

}  // namespace driftlab::ui
