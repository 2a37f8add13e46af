#include "db/PushHistory.h"

#include <QJsonDocument>
#include <QSqlError>
#include <QSqlQuery>

#include "db/SqlValues.h"
#include "db/StoreBackend.h"

namespace driftlab::db {

std::optional<qint64> storePush(CampaignStore& store, const PushRecord& push, QString* error) {
    QSqlQuery q(store.database());
    q.prepare(QStringLiteral(
        "INSERT INTO compensation_push (campaign_id, run, controller_url, table_version, points, "
        "table_checksum, table_json, result, message, steps_json) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"));
    q.addBindValue(push.campaign_id ? QVariant(*push.campaign_id) : QVariant());
    q.addBindValue(text(push.run));
    q.addBindValue(text(push.controller_url));
    q.addBindValue(push.table_version);
    q.addBindValue(push.points);
    q.addBindValue(push.table_checksum);
    q.addBindValue(QString::fromUtf8(QJsonDocument(push.table).toJson(QJsonDocument::Compact)));
    q.addBindValue(text(push.result));
    q.addBindValue(text(push.message));
    q.addBindValue(QString::fromUtf8(QJsonDocument(push.steps).toJson(QJsonDocument::Compact)));
    if (!q.exec()) {
        *error = QStringLiteral("%1: cannot record the push to %2: %3")
                     .arg(store.path(), push.controller_url, q.lastError().text());
        return std::nullopt;
    }
    return insertedRowId(store.database(), q);
}

std::optional<std::vector<PushRecord>> pushHistory(CampaignStore& store,
                                                   std::optional<qint64> campaignId,
                                                   QString* error) {
    QSqlQuery q(store.database());
    q.prepare(QStringLiteral(
                  "SELECT id, pushed_at, campaign_id, run, controller_url, table_version, points, "
                  "table_checksum, table_json, result, message, steps_json "
                  "FROM compensation_push %1 ORDER BY id")
                  .arg(campaignId ? QStringLiteral("WHERE campaign_id = ?") : QString()));
    if (campaignId) q.addBindValue(*campaignId);
    if (!q.exec()) {
        *error = QStringLiteral(
                     "%1: no push history readable (%2); a store of schema v3 gets "
                     "one when opened for writing")
                     .arg(store.path(), q.lastError().text());
        return std::nullopt;
    }
    std::vector<PushRecord> pushes;
    while (q.next()) {
        PushRecord r;
        r.id = q.value(0).toLongLong();
        r.pushed_at = q.value(1).toString();
        if (!q.value(2).isNull()) r.campaign_id = q.value(2).toLongLong();
        r.run = q.value(3).toString();
        r.controller_url = q.value(4).toString();
        r.table_version = q.value(5).toInt();
        r.points = q.value(6).toInt();
        r.table_checksum = q.value(7).toInt();
        r.table = QJsonDocument::fromJson(q.value(8).toByteArray()).object();
        r.result = q.value(9).toString();
        r.message = q.value(10).toString();
        r.steps = QJsonDocument::fromJson(q.value(11).toByteArray()).array();
        pushes.push_back(std::move(r));
    }
    return pushes;
}

}  // namespace driftlab::db
