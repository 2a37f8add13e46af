#pragma once
// A push as a row of the store's push history (db/PushHistory.h): what the
// CLI's `compensate --push` and the GUI's Compensation page record.

#include <QJsonObject>
#include <optional>

#include "acquisition/push/PushResult.h"
#include "core/compensation/CompensationTable.h"
#include "db/PushHistory.h"

namespace driftlab::push {

/// start_mm, spacing_mm, points, bidirectional, correction_plus_um (and
/// correction_minus_um for a bidirectional table).
QJsonObject tableJson(const compensation::CompensationTable& table);

/// The history row of `result` for `table`, pushed from `run` of the campaign.
db::PushRecord pushRecord(const compensation::CompensationTable& table,
                          std::optional<qint64> campaignId, const QString& run,
                          const PushResult& result);

/// Appends `record` to the push history of the store at `storePath` (opened
/// for writing on the calling thread); false with `error`.
bool recordPush(const QString& storePath, const db::PushRecord& record, QString* error);

}  // namespace driftlab::push
