#include "ui/shell/CampaignImportFlow.h"

#include <QFileInfo>
#include <QMimeData>
#include <QProgressDialog>
#include <QTemporaryDir>
#include <QUrl>
#include <memory>

#include "core/bundle/BundleWriter.h"
#include "core/interferometer/InterferometerCsvImport.h"

#include "db/CampaignImport.h"
#include "db/CampaignStore.h"
#include "db/ZipBundleSource.h"
#include "ui/shell/BackgroundJob.h"
#include "ui/shell/Session.h"
#include "ui/widgets/ImportProblemsDialog.h"

namespace driftlab::ui {

struct ImportOutcome {
    std::optional<qint64> campaignId;
    QString name;
    QString error;  ///< why nothing was stored; empty when stored or cancelled
    QStringList warnings;
};

namespace {

constexpr int kImportSteps = 1000;
/// The check reads the bundle once, the import once more: half each.
constexpr double kCheckShare = 0.5;

/// Both passes, on the worker: connections of its own (a QSqlDatabase
/// belongs to its thread), the store opened for writing only for a good bundle.
void importOnWorker(const QString& path, const QString& storePath, JobControl& control,
                    ImportOutcome& out) {
    QString error;
    const auto source = db::openBundleSource(path, &error);
    if (!source) {
        out.error = error;
        return;
    }
    const db::BundleCheck checked = db::checkBundle(
        *source, [&control](double f) { return control.progress(kCheckShare * f); });
    out.name = checked.name;
    out.warnings = checked.warnings;
    if (control.cancelled()) return;
    if (!checked.ok()) {
        out.error = checked.error;
        return;
    }
    if (auto reader = db::CampaignStore::open(storePath, db::StoreAccess::ReadOnly, &error))
        if (auto why = db::alreadyImported(*reader, *source, checked)) {
            out.error = *why;
            return;
        }
    auto store = db::CampaignStore::open(storePath, db::StoreAccess::ReadWrite, &error);
    if (!store) {
        out.error = error;
        return;
    }
    db::BundleImportOptions options;
    options.progress = [&control](double f) {
        return control.progress(kCheckShare + (1 - kCheckShare) * f);
    };
    const db::BundleImportResult result = db::importBundle(*store, *source, checked, options);
    error = result.error;
    if (!result.campaignId || !store->publish(&error)) {
        if (!control.cancelled()) out.error = error;
        return;
    }
    out.campaignId = result.campaignId;
}

/// The CSV read and built into a campaign, written as a bundle in a temporary
/// folder (removed after), then stored as any bundle: every check of the
/// bundle reader applies, and the problems list shows its errors.
void importCsvOnWorker(const InterferometerCsvRequest& request, const QString& storePath,
                       JobControl& control, ImportOutcome& out) {
    const interferometer::InterferometerCsvImport read =
        interferometer::importInterferometerCsv(request.path, request.header, request.mapping);
    if (read.error) {
        out.error = read.error->toString();
        return;
    }
    const interferometer::PositioningRunBuild built =
        interferometer::buildPositioningCampaign(read.readings, request.context);
    if (built.error) {
        out.error = built.error->toString();
        return;
    }
    if (control.cancelled()) return;
    const QTemporaryDir staging;
    if (!staging.isValid()) {
        out.error = QStringLiteral("cannot make a temporary folder: %1").arg(staging.errorString());
        return;
    }
    const QString bundle = staging.filePath(QStringLiteral("bundle"));
    if (const auto error = bundle::writeBundle(*built.campaign, bundle)) {
        out.error = error->toString();
        return;
    }
    importOnWorker(bundle, storePath, control, out);
}

}  // namespace

CampaignImportFlow::CampaignImportFlow(Session& session, QWidget* dialogParent)
    : QObject(dialogParent),
      m_session(session),
      m_job(new BackgroundJob(this)),
      m_progress(new QProgressDialog(dialogParent)),
      m_problems(new ImportProblemsDialog(dialogParent)) {
    m_progress->setWindowTitle(tr("Import campaign"));
    m_progress->setRange(0, kImportSteps);
    m_progress->setAutoClose(false);
    m_progress->setAutoReset(false);
    m_progress->setMinimumDuration(0);
    m_progress->setWindowModality(Qt::WindowModal);
    m_progress->reset();
    m_progress->hide();
    connect(m_progress, &QProgressDialog::canceled, m_job, &BackgroundJob::cancel);
    connect(m_job, &BackgroundJob::progressChanged, this, [this](double f) {
        if (f < 0) return;
        m_progress->setLabelText(f < kCheckShare ? tr("Checking the bundle…")
                                                 : tr("Storing the campaign…"));
        m_progress->setValue(int(kImportSteps * f));
    });
}

CampaignImportFlow::~CampaignImportFlow() = default;

bool CampaignImportFlow::isRunning() const {
    return m_job->isRunning();
}

bool CampaignImportFlow::start(const QString& path, QString* why) {
    return launch(path, why, [path](const QString& store, JobControl& control, ImportOutcome& out) {
        importOnWorker(path, store, control, out);
    });
}

bool CampaignImportFlow::startInterferometerCsv(const InterferometerCsvRequest& request,
                                                QString* why) {
    return launch(request.path, why,
                  [request](const QString& store, JobControl& control, ImportOutcome& out) {
                      importCsvOnWorker(request, store, control, out);
                  });
}

bool CampaignImportFlow::launch(
    const QString& path, QString* why,
    std::function<void(const QString& store, JobControl&, ImportOutcome&)> work) {
    if (m_session.storePath().isEmpty()) {
        if (why) *why = tr("no store is open: open or create one, then import");
        return false;
    }
    if (isRunning()) {
        if (why) *why = tr("an import is running: wait for it or cancel it");
        return false;
    }
    const QString store = m_session.storePath();
    m_progress->setLabelText(tr("Checking the bundle…"));
    m_progress->setValue(0);
    m_progress->show();
    auto outcome = std::make_shared<ImportOutcome>();
    m_job->start([work = std::move(work), store,
                  outcome](JobControl& control) { work(store, control, *outcome); },
                 [this, path, store, outcome] { report(path, store, *outcome); });
    return true;
}

void CampaignImportFlow::report(const QString& path, const QString& store,
                                const ImportOutcome& outcome) {
    m_progress->hide();
    const QString source = QStringLiteral("import");
    for (const QString& w : outcome.warnings)
        emit m_session.event(QStringLiteral("warning"), source, w);
    if (outcome.campaignId) {
        emit m_session.event(QStringLiteral("info"), source,
                             tr("%1 imported as campaign %2 ('%3')")
                                 .arg(path)
                                 .arg(*outcome.campaignId)
                                 .arg(outcome.name));
        m_session.notifyStoreChanged();
        m_session.selectCampaign(outcome.campaignId);
    } else if (outcome.error.isEmpty()) {
        emit m_session.event(QStringLiteral("info"), source,
                             tr("import of %1 cancelled: nothing stored").arg(path));
    } else {
        emit m_session.event(QStringLiteral("error"), source,
                             tr("%1 not imported: %2").arg(path, outcome.error));
        m_problems->showProblems(path, store, {outcome.error}, outcome.warnings);
    }
    emit finished(outcome.campaignId);
}

bool CampaignImportFlow::isInterferometerCsv(const QString& path) {
    return path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive);
}

std::optional<QString> CampaignImportFlow::bundleOf(const QMimeData* mime) {
    if (!mime || !mime->hasUrls() || mime->urls().size() != 1) return std::nullopt;
    const QUrl url = mime->urls().front();
    if (!url.isLocalFile()) return std::nullopt;
    const QFileInfo info(url.toLocalFile());
    if (info.isDir() || info.suffix().compare(QLatin1String("zip"), Qt::CaseInsensitive) == 0 ||
        isInterferometerCsv(info.fileName()))
        return info.absoluteFilePath();
    return std::nullopt;
}

}  // namespace driftlab::ui
