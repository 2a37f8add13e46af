#include "acquisition/push/PushRecording.h"

#include <QJsonArray>

namespace driftlab::push {

QJsonObject tableJson(const compensation::CompensationTable& table) {
    QJsonArray plus, minus;
    for (std::size_t i = 0; i < table.size(); ++i) {
        plus.append(table.correction_plus_um[i]);
        minus.append(table.correction_minus_um[i]);
    }
    QJsonObject json{{QStringLiteral("start_mm"), table.position_mm.front()},
                     {QStringLiteral("spacing_mm"), table.spacing_mm()},
                     {QStringLiteral("points"), int(table.size())},
                     {QStringLiteral("bidirectional"), table.bidirectional},
                     {QStringLiteral("correction_plus_um"), plus}};
    if (table.bidirectional) json[QStringLiteral("correction_minus_um")] = minus;
    return json;
}

db::PushRecord pushRecord(const compensation::CompensationTable& table,
                          std::optional<qint64> campaignId, const QString& run,
                          const PushResult& result) {
    db::PushRecord push;
    push.campaign_id = campaignId;
    push.run = run;
    push.controller_url = result.controller;
    push.table_version = result.version;
    push.points = int(table.size());
    push.table_checksum = result.checksum;
    push.table = tableJson(table);
    push.result = outcomeName(result.outcome);
    push.message = result.message;
    push.steps = result.toJson()[QStringLiteral("steps")].toArray();
    return push;
}

bool recordPush(const QString& storePath, const db::PushRecord& record, QString* error) {
    auto store = db::CampaignStore::open(storePath, db::StoreAccess::ReadWrite, error);
    return store && db::storePush(*store, record, error);
}

}  // namespace driftlab::push
