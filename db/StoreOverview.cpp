#include "db/StoreOverview.h"

#include <QSqlError>
#include <QSqlQuery>

namespace driftlab::db {

std::optional<std::vector<CampaignOverview>> storeOverview(CampaignStore& store, QString* error) {
    std::vector<CampaignOverview> campaigns;
    for (const CampaignSummary& c : store.listCampaigns())
        campaigns.push_back({c.id, c.name, {}, {}, {}, {}});
    QSqlQuery q(store.database());
    if (!q.exec(QStringLiteral(
            "SELECT r.campaign_id, r.id, r.name, r.kind, r.status, "
            "(SELECT coalesce(sum(row_count), 0) FROM sample_block WHERE run_id = r.id), "
            "(SELECT count(*) FROM positioning WHERE run_id = r.id) "
            "FROM run r ORDER BY r.campaign_id, r.ordinal"))) {
        if (error) *error = store.path() + QStringLiteral(": ") + q.lastError().text();
        return std::nullopt;
    }
    while (q.next())
        for (auto& c : campaigns)
            if (c.id == q.value(0).toLongLong())
                c.runs.push_back({q.value(1).toLongLong(), q.value(2).toString(),
                                  q.value(3).toString(), q.value(4).toString(),
                                  q.value(5).toLongLong(), q.value(6).toLongLong()});
    for (auto& c : campaigns) {
        c.fits = modelFits(store, c.id);
        c.diagnoses = diagnoses(store, c.id);
        QString why;
        // A store written before the push history (v3) simply has no pushes.
        c.pushes = pushHistory(store, c.id, &why).value_or(std::vector<PushRecord>{});
    }
    return campaigns;
}

}  // namespace driftlab::db
