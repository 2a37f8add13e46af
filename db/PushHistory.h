#pragma once
// The compensation push history (table compensation_push, schema v4): every
// push with when, which table, which controller and what happened.

#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <optional>
#include <vector>

#include "db/CampaignStore.h"

namespace driftlab::db {

struct PushRecord {
    qint64 id = 0;                      ///< set when read back
    QString pushed_at;                  ///< UTC, ISO 8601; set by the store when written
    std::optional<qint64> campaign_id;  ///< none for a push from a bundle folder
    QString run;
    QString controller_url;
    int table_version = 0;
    int points = 0;
    int table_checksum = 0;
    QJsonObject table;  ///< start_mm, spacing_mm, correction_plus_um, correction_minus_um, …
    QString result;     ///< applied, rolled_back, refused, failed
    QString message;
    QJsonArray steps;  ///< [{step, ok, detail}]
};

/// Appends a push; returns its id, or nullopt with `error`.
std::optional<qint64> storePush(CampaignStore& store, const PushRecord& push, QString* error);
/// The pushes, oldest first; of one campaign when `campaignId` is given.
/// nullopt with `error` when the store has no v4 history (open it for writing once).
std::optional<std::vector<PushRecord>> pushHistory(CampaignStore& store,
                                                   std::optional<qint64> campaignId,
                                                   QString* error);

}  // namespace driftlab::db
