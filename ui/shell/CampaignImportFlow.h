#pragma once
// File → Import campaign… and a bundle dropped on the window: a bundle folder
// or its .zip stored in the session's store as `driftlab-cli import` does
// (db/CampaignImport's two passes), on a worker (BackgroundJob) under a
// progress dialog with Cancel. The check pass reads the whole bundle before
// the store is opened for writing, so a bad bundle leaves the store byte for
// byte as it was; its errors are listed in an ImportProblemsDialog.

#include <QObject>
#include <QString>
#include <optional>

class QMimeData;
class QProgressDialog;
class QWidget;

namespace driftlab::ui {

class BackgroundJob;
class ImportProblemsDialog;
struct ImportOutcome;
class Session;

class CampaignImportFlow : public QObject {
    Q_OBJECT
public:
    CampaignImportFlow(Session& session, QWidget* dialogParent);
    ~CampaignImportFlow() override;

    /// Starts importing `path` (a bundle folder or .zip); false with `why`
    /// when refused at once (no store open, an import running).
    bool start(const QString& path, QString* why);
    bool isRunning() const;
    BackgroundJob& job() const { return *m_job; }
    ImportProblemsDialog* problemsDialog() const { return m_problems; }

    /// The one local folder or .zip a drag carries, if it carries just that.
    static std::optional<QString> bundleOf(const QMimeData* mime);

signals:
    /// The import ended: the campaign's id when stored, nullopt when refused
    /// or cancelled (nothing stored).
    void finished(std::optional<qint64> campaignId);

private:
    /// Back on the GUI thread: the event log, the selection, or the problems.
    void report(const QString& path, const QString& store, const ImportOutcome& outcome);

    Session& m_session;
    BackgroundJob* m_job;
    QProgressDialog* m_progress;
    ImportProblemsDialog* m_problems;
};

}  // namespace driftlab::ui
