#pragma once
// The work behind the sensor-health page, run on a worker (BackgroundJob):
// read a campaign's stored flags with the samples each leaves out, check a
// run as `driftlab-cli health --store` does, and keep or mask flagged
// stretches. Each opens its own store connection (a QSqlDatabase belongs to
// the thread that opened it).

#include <QString>
#include <map>
#include <vector>

#include "core/domain/Campaign.h"
#include "core/sensors/SensorHealth.h"
#include "db/SampleFlagStore.h"

namespace driftlab::ui {

/// A stored flag and the present samples of its channel inside its stretch.
struct ShownFlag {
    db::StoredFlag flag;
    std::size_t samples = 0;
};

struct CampaignFlags {
    QString error;                                   ///< empty on success
    std::map<QString, std::vector<ShownFlag>> runs;  ///< by run name; runs without flags absent
    /// What the models leave out: the samples of the stretches not kept
    /// (a sample in two stretches counts once), by run name.
    std::map<QString, std::size_t> left_out;
};

/// The flags of campaign `campaignId` (loaded as `campaign`) in the store at `storePath`.
CampaignFlags loadCampaignFlags(const QString& storePath, qint64 campaignId,
                                const Campaign& campaign);

/// Checks run `runName`, with the `redundant` pairs, and replaces its stored
/// flags (db::flagRun); an error or "".
QString checkRunFlags(const QString& storePath, qint64 campaignId, const QString& runName,
                      const std::vector<sensors::RedundantPair>& redundant = {});

/// Keeps (`kept`) or masks again the stored flags `flagIds`; an error or "".
QString keepFlags(const QString& storePath, const std::vector<qint64>& flagIds, bool kept);

}  // namespace driftlab::ui
