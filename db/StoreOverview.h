#pragma once
// What a store holds, for the GUI's campaign tree: campaigns with their runs
// (kind, status, counts), fits, diagnoses and compensation pushes. One
// read-only pass of small queries; no sample is read.

#include <QString>
#include <optional>
#include <vector>

#include "db/CampaignStore.h"
#include "db/DiagnosisStore.h"
#include "db/ModelFitStore.h"
#include "db/PushHistory.h"

namespace driftlab::db {

struct RunOverview {
    qint64 id = 0;
    QString name;
    QString kind;
    QString status;  ///< complete, logging, interrupted
    qint64 rows = 0;
    qint64 readings = 0;
};

struct CampaignOverview {
    qint64 id = 0;
    QString name;
    std::vector<RunOverview> runs;
    std::vector<ModelFitRecord> fits;
    std::vector<DiagnosisRecord> diagnoses;
    std::vector<PushRecord> pushes;
};

/// Every campaign of the store, oldest first; nullopt with `error`.
std::optional<std::vector<CampaignOverview>> storeOverview(CampaignStore& store, QString* error);

}  // namespace driftlab::db
