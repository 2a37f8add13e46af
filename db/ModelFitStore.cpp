#include "db/ModelFitStore.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QSqlError>
#include <QSqlQuery>

#include "db/StoreBackend.h"

namespace driftlab::db {
namespace {

QString compact(const QJsonDocument& document) {
    return QString::fromUtf8(document.toJson(QJsonDocument::Compact));
}

}  // namespace

std::optional<qint64> storeModelFit(CampaignStore& store, qint64 campaignId,
                                    const ModelFitRecord& fit, QString* error) {
    QSqlQuery q(store.database());
    q.prepare(QStringLiteral(
        "INSERT INTO model_fit (campaign_id, model, target, train_runs_json, test_runs_json, "
        "parameters_json, metrics_json) VALUES (?, ?, ?, ?, ?, ?, ?)"));
    q.addBindValue(campaignId);
    q.addBindValue(fit.model);
    q.addBindValue(fit.target);
    q.addBindValue(compact(QJsonDocument(QJsonArray::fromStringList(fit.train_runs))));
    q.addBindValue(compact(QJsonDocument(QJsonArray::fromStringList(fit.test_runs))));
    q.addBindValue(compact(QJsonDocument(fit.parameters)));
    q.addBindValue(compact(QJsonDocument(fit.metrics)));
    if (!q.exec()) {
        *error = QStringLiteral("%1: cannot store the %2 fit of campaign %3: %4")
                     .arg(store.path(), fit.model)
                     .arg(campaignId)
                     .arg(q.lastError().text());
        return std::nullopt;
    }
    return insertedRowId(store.database(), q);
}

std::vector<ModelFitRecord> modelFits(CampaignStore& store, qint64 campaignId) {
    QSqlQuery q(store.database());
    q.prepare(QStringLiteral(
        "SELECT id, model, target, train_runs_json, test_runs_json, parameters_json, "
        "metrics_json FROM model_fit WHERE campaign_id = ? ORDER BY id"));
    q.addBindValue(campaignId);
    std::vector<ModelFitRecord> fits;
    if (!q.exec()) return fits;
    auto runs = [](const QVariant& v) {
        QStringList ids;
        for (const auto& id : QJsonDocument::fromJson(v.toByteArray()).array())
            ids << id.toString();
        return ids;
    };
    while (q.next())
        fits.push_back({q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(),
                        runs(q.value(3)), runs(q.value(4)),
                        QJsonDocument::fromJson(q.value(5).toByteArray()).object(),
                        QJsonDocument::fromJson(q.value(6).toByteArray()).object()});
    return fits;
}

}  // namespace driftlab::db
