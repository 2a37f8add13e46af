#pragma once
// Diagnoses kept with their campaign (table diagnosis): the verdict, the whole
// result as JSON, and the model fit of the adopted extension.

#include <QJsonObject>
#include <optional>

#include "db/CampaignStore.h"

namespace driftlab::db {

struct DiagnosisRecord {
    qint64 id = 0;
    QString base_model;
    QString verdict;
    std::optional<qint64> adopted_fit_id;
    QJsonObject result;
};

std::optional<qint64> storeDiagnosis(CampaignStore& store, qint64 campaignId,
                                     const DiagnosisRecord& diagnosis, QString* error);
/// Records `fitId` as the adopted extension of stored diagnosis `diagnosisId`.
bool setAdoptedFit(CampaignStore& store, qint64 diagnosisId, qint64 fitId, QString* error);
std::vector<DiagnosisRecord> diagnoses(CampaignStore& store, qint64 campaignId);

}  // namespace driftlab::db
