#pragma once
// File → Export campaign…: the selected campaign written as a bundle folder,
// as `driftlab-cli export --out DIR` writes it (core/bundle/BundleWriter: a
// new or empty folder, written beside it and renamed into place, so the
// folder holds the whole bundle or nothing). The campaign is read and
// written on a worker (BackgroundJob); the window stays live meanwhile.

#include <QObject>
#include <QString>

namespace driftlab::ui {

class BackgroundJob;
class Session;

class CampaignExportFlow : public QObject {
    Q_OBJECT
public:
    explicit CampaignExportFlow(Session& session, QObject* parent = nullptr);

    /// Starts writing the selected campaign to `directory`; false when no
    /// campaign is selected or an export is running.
    bool start(const QString& directory);
    bool isRunning() const;

signals:
    /// `message`: the folder written, or why nothing was written.
    void finished(bool written, const QString& message);

private:
    Session& m_session;
    BackgroundJob* m_job;
};

}  // namespace driftlab::ui
