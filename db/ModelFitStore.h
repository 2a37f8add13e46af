#pragma once
// Model fits kept with their campaign: which model, on which runs it was
// trained and tested, its parameters and its figures (table model_fit).

#include <QJsonObject>
#include <QStringList>
#include <optional>
#include <vector>

#include "db/CampaignStore.h"

namespace driftlab::db {

struct ModelFitRecord {
    qint64 id = 0;  ///< set when read back
    QString model;
    QString target = QStringLiteral("positioning");  ///< or the drift channel id
    QStringList train_runs, test_runs;
    QJsonObject parameters;  ///< NAME: {"value", "sigma", "unit"}
    QJsonObject metrics;     ///< the fit and test figures
};

/// Stores a fit of campaign `campaignId`; returns its id, or nullopt with `error`.
std::optional<qint64> storeModelFit(CampaignStore& store, qint64 campaignId,
                                    const ModelFitRecord& fit, QString* error);
/// The fits of a campaign, oldest first.
std::vector<ModelFitRecord> modelFits(CampaignStore& store, qint64 campaignId);

}  // namespace driftlab::db
