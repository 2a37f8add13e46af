#include "ui/shell/Session.h"

#include <QFileInfo>

#include "db/CampaignStore.h"
#include "db/StoreBackend.h"

namespace driftlab::ui {

Session::Session(QObject* parent) : QObject(parent) {
    qRegisterMetaType<std::optional<qint64>>();
}

bool Session::openStore(const QString& path, bool create, QString* error) {
    const bool server = db::isServerStoreUrl(path);
    if (create && !server && !QFileInfo::exists(path)) {
        auto store = db::CampaignStore::open(path, db::StoreAccess::CreateIfMissing, error);
        if (!store || !store->publish(error)) return false;
    }
    // Checked read-only: a file that is not a DriftLab store is refused here.
    if (!db::CampaignStore::open(path, db::StoreAccess::ReadOnly, error)) return false;
    m_storePath = server ? path : QFileInfo(path).absoluteFilePath();
    m_campaignId.reset();
    emit storeChanged(m_storePath);
    emit campaignSelected(m_campaignId);
    return true;
}

void Session::selectCampaign(std::optional<qint64> id) {
    if (id == m_campaignId) return;
    m_campaignId = id;
    emit campaignSelected(id);
}

void Session::setRunSetup(const RunSetup& setup) {
    m_runSetup = setup;
    emit runSetupChanged();
}

void Session::notifyStoreChanged() {
    emit storeContentChanged();
}

std::optional<Campaign> Session::loadCampaign(QString* error) const {
    if (m_storePath.isEmpty() || !m_campaignId) {
        if (error) *error = tr("no campaign selected");
        return std::nullopt;
    }
    auto store = db::CampaignStore::open(m_storePath, db::StoreAccess::ReadOnly, error);
    if (!store) return std::nullopt;
    return store->loadCampaign(*m_campaignId, error);
}

}  // namespace driftlab::ui
