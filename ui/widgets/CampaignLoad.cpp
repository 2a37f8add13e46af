#include "ui/widgets/CampaignLoad.h"

#include "core/iso/PositioningRuns.h"

#include <QSignalBlocker>

#include <QComboBox>

#include <QtConcurrent/QtConcurrentRun>

#include "db/CampaignStore.h"
#include "db/DiagnosisRecords.h"

namespace driftlab::ui {

std::vector<db::PushRecord> campaignPushes(const QString& storePath, qint64 campaignId) {
    QString error;
    auto store = db::CampaignStore::open(storePath, db::StoreAccess::ReadOnly, &error);
    if (!store) return {};
    // A store never pushed from has no history table yet: an empty history.
    auto pushes = db::pushHistory(*store, campaignId, &error);
    return pushes ? std::move(*pushes) : std::vector<db::PushRecord>{};
}

QFuture<LoadedCampaign> loadCampaignInBackground(const QString& storePath, qint64 campaignId,
                                                 bool withPushes) {
    return QtConcurrent::run([storePath, campaignId, withPushes] {
        LoadedCampaign loaded;
        auto store = db::CampaignStore::open(storePath, db::StoreAccess::ReadOnly, &loaded.error);
        if (!store) return loaded;
        loaded.campaign = store->loadCampaign(campaignId, &loaded.error);
        if (loaded.campaign)
            loaded.adopted_extensions = db::adoptedExtensionModels(*store, campaignId);
        store.reset();
        if (loaded.campaign && withPushes) loaded.pushes = campaignPushes(storePath, campaignId);
        return loaded;
    });
}

void fillPositioningRunBox(QComboBox* box, const Campaign& campaign) {
    const QString previous = box->currentText();
    const QStringList runs = iso::runsWithPositioning(campaign);
    const QSignalBlocker block(box);
    box->clear();
    box->addItems(runs);
    const QString wanted =
        runs.contains(previous) ? previous : iso::defaultPositioningRun(campaign).id;
    box->setCurrentIndex(wanted.isEmpty() ? 0 : int(runs.indexOf(wanted)));
}

}  // namespace driftlab::ui
