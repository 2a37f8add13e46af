#pragma once
// File → Import campaign… and a bundle dropped on the window: a bundle folder
// or its .zip stored in the session's store as `driftlab-cli import` does
// (db/CampaignImport's two passes), on a worker (BackgroundJob) under a
// progress dialog with Cancel. The check pass reads the whole bundle before
// the store is opened for writing, so a bad bundle leaves the store byte for
// byte as it was; its errors are listed in an ImportProblemsDialog.
//
// An interferometer software's CSV export comes the same way: read through
// the user's column mapping, built into a campaign with one positioning run
// (core/interferometer/InterferometerRunBuilder), written as a bundle folder
// in a temporary directory and then checked and stored as any bundle, so its
// errors land in the same list and a bad one stores nothing.

#include <QObject>
#include <QString>
#include <functional>
#include <optional>

#include "core/interferometer/InterferometerColumns.h"
#include "core/interferometer/InterferometerLine.h"
#include "core/interferometer/InterferometerRunBuilder.h"

class QMimeData;
class QProgressDialog;
class QWidget;

namespace driftlab::ui {

class BackgroundJob;
class ImportProblemsDialog;
struct ImportOutcome;
class JobControl;
class Session;

/// What the interferometer CSV dialog collected: the file, how to read it and
/// what campaign to make of it.
struct InterferometerCsvRequest {
    QString path;
    interferometer::InterferometerHeader header;
    interferometer::ColumnMapping mapping;
    interferometer::PositioningRunContext context;
};

class CampaignImportFlow : public QObject {
    Q_OBJECT
public:
    CampaignImportFlow(Session& session, QWidget* dialogParent);
    ~CampaignImportFlow() override;

    /// Starts importing `path` (a bundle folder or .zip); false with `why`
    /// when refused at once (no store open, an import running).
    bool start(const QString& path, QString* why);
    /// Starts importing an interferometer CSV export as a new campaign.
    bool startInterferometerCsv(const InterferometerCsvRequest& request, QString* why);
    bool isRunning() const;
    BackgroundJob& job() const { return *m_job; }
    ImportProblemsDialog* problemsDialog() const { return m_problems; }

    /// The one local folder, .zip or .csv a drag carries, if it carries just that.
    static std::optional<QString> bundleOf(const QMimeData* mime);
    /// A file ending in .csv: an interferometer export, to map before import.
    static bool isInterferometerCsv(const QString& path);

signals:
    /// The import ended: the campaign's id when stored, nullopt when refused
    /// or cancelled (nothing stored).
    void finished(std::optional<qint64> campaignId);

private:
    /// Runs `work` on the worker for `path`, then report().
    bool launch(const QString& path, QString* why,
                std::function<void(const QString& store, JobControl&, ImportOutcome&)> work);
    /// Back on the GUI thread: the event log, the selection, or the problems.
    void report(const QString& path, const QString& store, const ImportOutcome& outcome);

    Session& m_session;
    BackgroundJob* m_job;
    QProgressDialog* m_progress;
    ImportProblemsDialog* m_problems;
};

}  // namespace driftlab::ui
