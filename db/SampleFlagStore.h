#pragma once
// Sensor flags in the store (table sample_flag, schema v5): what the sensor
// self-diagnosis found in a run's samples, as time ranges per channel and
// kind. Written by `driftlab-cli health --store` and the GUI's sensor-health
// page; read by the commands that fit or run models, which leave flagged
// samples out unless told otherwise: --keep-flagged for all, or a stretch
// the user kept (schema v7; docs/sensor-health.md, "Flags in the store").

#include <QString>
#include <map>
#include <optional>
#include <vector>

#include "core/sensors/SampleFlags.h"
#include "db/CampaignStore.h"

namespace driftlab::db {

/// Replaces the flags of run `runDbId` (run.id) with `ranges` in one
/// transaction; a range found again keeps the user's choice to keep it.
/// False with `error` ("PATH: why") on failure; nothing changed then.
bool replaceRunFlags(CampaignStore& store, qint64 runDbId,
                     const std::vector<sensors::FlaggedRange>& ranges, QString* error);

/// Loads run `runDbId`'s samples, runs sensors::checkRun over them (with
/// `redundant` pairs), replaces the run's flags with what it found and
/// returns those ranges; nullopt with `error` on failure.
std::optional<std::vector<sensors::FlaggedRange>> flagRun(
    CampaignStore& store, qint64 runDbId, const sensors::SensorHealthSettings& settings,
    QString* error, const std::vector<sensors::RedundantPair>& redundant = {});

/// The run.id of run `runName` of campaign `campaignId`; nullopt with `error`.
std::optional<qint64> runDbId(CampaignStore& store, qint64 campaignId, const QString& runName,
                              QString* error);

/// The stored flags of a campaign, by run name (runs without flags are not
/// listed). Empty for a store of schema v4 or older read without migrating
/// (no flags can be stored there); nullopt with `error` on a database error.
std::optional<std::map<QString, std::vector<sensors::FlaggedRange>>> loadSampleFlags(
    CampaignStore& store, qint64 campaignId, QString* error);

/// A stored flag: its row, its range, and whether the user keeps its samples
/// for the models (they are left out otherwise).
struct StoredFlag {
    qint64 id = 0;  ///< sample_flag.id
    sensors::FlaggedRange range;
    bool kept = false;
};

/// As loadSampleFlags, with each flag's row and keep choice (never kept in a
/// store older than v7 read without migrating).
std::optional<std::map<QString, std::vector<StoredFlag>>> loadStoredFlags(CampaignStore& store,
                                                                          qint64 campaignId,
                                                                          QString* error);

/// Keeps (`kept`) or leaves out again the samples of the stored flags `flagIds`,
/// in one transaction; false with `error` naming the flag when one is unknown
/// or the store cannot be written (nothing changed then).
bool setFlagsKept(CampaignStore& store, const std::vector<qint64>& flagIds, bool kept,
                  QString* error);

}  // namespace driftlab::db
