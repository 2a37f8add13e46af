#pragma once
// The session's selected campaign, loaded off the GUI thread whenever the
// selection or the store's content changes, for the pages that show one
// campaign. A change while a load runs loads again when it ends, so a page
// never shows a campaign that is no longer selected.

#include <QFutureWatcher>
#include <QObject>

#include "ui/widgets/CampaignLoad.h"

namespace driftlab::ui {

class Session;

class SelectedCampaignLoader : public QObject {
    Q_OBJECT
public:
    /// `withPushes`: also read the campaign's push history.
    SelectedCampaignLoader(Session& session, bool withPushes, QObject* parent);
    /// Waits for a load in progress (it holds its own connection).
    ~SelectedCampaignLoader() override;

public slots:
    void reload();

signals:
    /// No store open or no campaign selected.
    void cleared();
    void loadingStarted();
    /// The campaign, or why it could not be read (`campaign` empty, `error`).
    void loaded(const driftlab::ui::LoadedCampaign& result);

private:
    void finished();

    Session& m_session;
    bool m_withPushes;
    QFutureWatcher<LoadedCampaign> m_loading;
    bool m_reloadAgain = false;
};

}  // namespace driftlab::ui
