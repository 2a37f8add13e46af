#include "ui/shell/SpoolSync.h"

#include <memory>
#include <optional>

#include "db/CampaignStore.h"
#include "db/SpoolFile.h"
#include "ui/shell/BackgroundJob.h"

namespace driftlab::ui {
namespace {

struct SpoolPass {
    std::optional<db::UploadReport> report;  ///< set after a successful upload
    std::optional<db::SpoolState> state;
    QString error;
};

}  // namespace

SpoolSync::SpoolSync(QObject* parent) : QObject(parent), m_job(new BackgroundJob(this)) {}

void SpoolSync::setStores(const QString& serverUrl, const QString& spoolPath) {
    m_server = serverUrl;
    m_spool = spoolPath;
    m_lastUpload.clear();
}

bool SpoolSync::isRunning() const {
    return m_job->isRunning();
}

bool SpoolSync::refresh() {
    if (isRunning() || m_server.isEmpty()) return false;
    run(false);
    return true;
}

bool SpoolSync::uploadNow() {
    if (isRunning() || m_server.isEmpty()) return false;
    run(true);
    return true;
}

void SpoolSync::run(bool upload) {
    auto pass = std::make_shared<SpoolPass>();
    m_job->start(
        [server = m_server, spool = m_spool, upload, pass](JobControl& control) {
            control.progress(-1);
            // Connections of its own: a QSqlDatabase belongs to its thread.
            auto store = db::CampaignStore::open(
                server, upload ? db::StoreAccess::ReadWrite : db::StoreAccess::ReadOnly,
                &pass->error);
            if (!store) return;
            if (upload && !(pass->report = db::syncSpool(spool, *store, &pass->error))) return;
            pass->state = db::spoolState(spool, *store, &pass->error);
        },
        [this, upload, pass] {
            if (upload) {
                const QString now =
                    QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss"));
                m_lastUpload = pass->report
                                   ? tr("last upload %1: %2 new runs, %3 sample blocks written")
                                         .arg(now)
                                         .arg(pass->report->runs)
                                         .arg(pass->report->blocks)
                                   : tr("last upload %1 stopped: %2").arg(now, pass->error);
                emit uploaded(pass->report.has_value(), pass->report ? m_lastUpload : pass->error);
            }
            const QString last =
                m_lastUpload.isEmpty() ? tr("no upload from this window yet") : m_lastUpload;
            if (pass->state)
                m_text = tr("%1 runs in the spool %2, %3 not on the server yet%4; %5")
                             .arg(pass->state->runs)
                             .arg(m_spool)
                             .arg(pass->state->pending)
                             .arg(pass->state->logging
                                      ? tr(" (%1 being logged)").arg(pass->state->logging)
                                      : QString())
                             .arg(last);
            else
                m_text = tr("spool %1 not read: %2; %3").arg(m_spool, pass->error, last);
            emit stateChanged(m_text);
        });
}

}  // namespace driftlab::ui
