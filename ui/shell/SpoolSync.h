#pragma once
// The spool of the lab store the window has open (docs/lab-store.md): what
// it holds that the server lacks, and Upload now (one `driftlab-cli sync`
// pass, db/SpoolFile), each on a worker (BackgroundJob) so a slow or absent
// server never blocks the window. There is no record of uploads in either
// store, so "last upload" is this window's last pass.

#include <QDateTime>
#include <QObject>
#include <QString>

namespace driftlab::ui {

class BackgroundJob;

class SpoolSync : public QObject {
    Q_OBJECT
public:
    explicit SpoolSync(QObject* parent = nullptr);

    /// The server store (a postgresql:// URL) and the spool file uploaded to it.
    void setStores(const QString& serverUrl, const QString& spoolPath);
    bool isRunning() const;
    /// "N runs in the spool, M not on the server yet; last upload …".
    QString stateText() const { return m_text; }

public slots:
    /// Reads the spool's state again; false while a pass runs.
    bool refresh();
    /// One upload pass, then the state read again; false while a pass runs.
    bool uploadNow();

signals:
    void stateChanged(const QString& text);
    /// An upload pass ended: what it copied, or why it stopped.
    void uploaded(bool ok, const QString& message);

private:
    void run(bool upload);

    BackgroundJob* m_job;
    QString m_server;
    QString m_spool;
    QString m_text;
    QString m_lastUpload;  ///< what the last pass did and when; empty before one
};

}  // namespace driftlab::ui
