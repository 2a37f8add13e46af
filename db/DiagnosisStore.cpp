#include "db/DiagnosisStore.h"

#include <QJsonDocument>
#include <QSqlError>
#include <QSqlQuery>

#include "db/StoreBackend.h"

namespace driftlab::db {

std::optional<qint64> storeDiagnosis(CampaignStore& store, qint64 campaignId,
                                     const DiagnosisRecord& d, QString* error) {
    QSqlQuery q(store.database());
    q.prepare(
        QStringLiteral("INSERT INTO diagnosis (campaign_id, base_model, verdict, "
                       "adopted_fit_id, result_json) VALUES (?, ?, ?, ?, ?)"));
    q.addBindValue(campaignId);
    q.addBindValue(d.base_model);
    q.addBindValue(d.verdict);
    q.addBindValue(d.adopted_fit_id ? QVariant(*d.adopted_fit_id) : QVariant());
    q.addBindValue(QString::fromUtf8(QJsonDocument(d.result).toJson(QJsonDocument::Compact)));
    if (!q.exec()) {
        *error = QStringLiteral("%1: cannot store the diagnosis of campaign %2: %3")
                     .arg(store.path())
                     .arg(campaignId)
                     .arg(q.lastError().text());
        return std::nullopt;
    }
    return insertedRowId(store.database(), q);
}

bool setAdoptedFit(CampaignStore& store, qint64 diagnosisId, qint64 fitId, QString* error) {
    QSqlQuery q(store.database());
    q.prepare(QStringLiteral("UPDATE diagnosis SET adopted_fit_id = ? WHERE id = ?"));
    q.addBindValue(fitId);
    q.addBindValue(diagnosisId);
    if (!q.exec() || q.numRowsAffected() != 1) {
        *error = QStringLiteral("%1: cannot record fit %2 as adopted by diagnosis %3: %4")
                     .arg(store.path())
                     .arg(fitId)
                     .arg(diagnosisId)
                     .arg(q.numRowsAffected() == 0 ? QStringLiteral("no such diagnosis")
                                                   : q.lastError().text());
        return false;
    }
    return true;
}

std::vector<DiagnosisRecord> diagnoses(CampaignStore& store, qint64 campaignId) {
    QSqlQuery q(store.database());
    q.prepare(
        QStringLiteral("SELECT id, base_model, verdict, adopted_fit_id, result_json FROM "
                       "diagnosis WHERE campaign_id = ? ORDER BY id"));
    q.addBindValue(campaignId);
    std::vector<DiagnosisRecord> out;
    if (!q.exec()) return out;
    while (q.next())
        out.push_back(
            {q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(),
             q.value(3).isNull() ? std::nullopt : std::optional<qint64>(q.value(3).toLongLong()),
             QJsonDocument::fromJson(q.value(4).toByteArray()).object()});
    return out;
}

}  // namespace driftlab::db
