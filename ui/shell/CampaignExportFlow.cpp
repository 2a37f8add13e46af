#include "ui/shell/CampaignExportFlow.h"

#include <memory>

#include "core/bundle/BundleWriter.h"
#include "db/CampaignStore.h"
#include "ui/shell/BackgroundJob.h"
#include "ui/shell/Session.h"

namespace driftlab::ui {

CampaignExportFlow::CampaignExportFlow(Session& session, QObject* parent)
    : QObject(parent), m_session(session), m_job(new BackgroundJob(this)) {}

bool CampaignExportFlow::isRunning() const {
    return m_job->isRunning();
}

bool CampaignExportFlow::start(const QString& directory) {
    const auto id = m_session.campaignId();
    if (!id || isRunning()) return false;
    const QString store = m_session.storePath();
    auto error = std::make_shared<QString>();
    m_job->start(
        [store, id = *id, directory, error](JobControl& control) {
            control.progress(-1);
            // A connection of its own: a QSqlDatabase belongs to its thread.
            auto reader = db::CampaignStore::open(store, db::StoreAccess::ReadOnly, error.get());
            const auto campaign = reader ? reader->loadCampaign(id, error.get()) : std::nullopt;
            if (!campaign) return;
            if (auto why = bundle::writeBundle(*campaign, directory)) *error = why->toString();
        },
        [this, directory, id = *id, error] {
            if (error->isEmpty())
                emit m_session.event(
                    QStringLiteral("info"), QStringLiteral("export"),
                    tr("campaign %1 written as a bundle to %2").arg(id).arg(directory));
            else
                emit m_session.event(QStringLiteral("error"), QStringLiteral("export"),
                                     tr("campaign %1 not exported: %2").arg(id).arg(*error));
            emit finished(error->isEmpty(), error->isEmpty() ? directory : *error);
        });
    return true;
}

}  // namespace driftlab::ui
