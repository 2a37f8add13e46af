#include "ui/shell/SelectedCampaignLoader.h"

#include "ui/shell/Session.h"

namespace driftlab::ui {

SelectedCampaignLoader::SelectedCampaignLoader(Session& session, bool withPushes, QObject* parent)
    : QObject(parent), m_session(session), m_withPushes(withPushes) {
    connect(&m_loading, &QFutureWatcher<LoadedCampaign>::finished, this,
            &SelectedCampaignLoader::finished);
    connect(&m_session, &Session::campaignSelected, this, &SelectedCampaignLoader::reload);
    connect(&m_session, &Session::storeContentChanged, this, &SelectedCampaignLoader::reload);
}

SelectedCampaignLoader::~SelectedCampaignLoader() {
    m_loading.waitForFinished();
}

void SelectedCampaignLoader::reload() {
    if (m_loading.isRunning()) {
        m_reloadAgain = true;  // the selection or the store changed while it loaded
        return;
    }
    const auto id = m_session.campaignId();
    if (m_session.storePath().isEmpty() || !id) {
        emit cleared();
        return;
    }
    emit loadingStarted();
    m_loading.setFuture(loadCampaignInBackground(m_session.storePath(), *id, m_withPushes));
}

void SelectedCampaignLoader::finished() {
    if (m_reloadAgain) {
        m_reloadAgain = false;
        return reload();
    }
    emit loaded(m_loading.result());
}

}  // namespace driftlab::ui
