#include "ui/shell/SensorFlagJob.h"

#include <cmath>

#include "core/sensors/SampleFlags.h"
#include "db/CampaignStore.h"

namespace driftlab::ui {
namespace {

/// The present samples of `range`'s channel inside it (what masking it removes).
std::size_t presentSamples(const Run& run, const sensors::FlaggedRange& range) {
    const int column = run.samples.columnIndex(range.channel);
    if (column < 0) return 0;
    const std::vector<double>& values = run.samples.values[std::size_t(column)];
    std::size_t n = 0;
    for (std::size_t i = 0; i < run.samples.time_s.size(); ++i)
        n += run.samples.time_s[i] >= range.from_s && run.samples.time_s[i] <= range.to_s &&
             !std::isnan(values[i]);
    return n;
}

}  // namespace

CampaignFlags loadCampaignFlags(const QString& storePath, qint64 campaignId,
                                const Campaign& campaign) {
    CampaignFlags out;
    auto store = db::CampaignStore::open(storePath, db::StoreAccess::ReadOnly, &out.error);
    if (!store) return out;
    const auto stored = db::loadStoredFlags(*store, campaignId, &out.error);
    if (!stored) return out;
    for (const Run& run : campaign.runs) {
        const auto found = stored->find(run.id);
        if (found == stored->end()) continue;
        std::vector<sensors::FlaggedRange> masked;
        for (const db::StoredFlag& flag : found->second) {
            out.runs[run.id].push_back({flag, presentSamples(run, flag.range)});
            if (!flag.kept) masked.push_back(flag.range);
        }
        // Counted on a copy, exactly as db::leaveOutFlaggedSamples masks it for a fit.
        Run copy = run;
        out.left_out[run.id] = sensors::maskFlaggedSamples(copy, masked);
    }
    return out;
}

QString checkRunFlags(const QString& storePath, qint64 campaignId, const QString& runName,
                      const std::vector<sensors::RedundantPair>& redundant) {
    QString error;
    auto store = db::CampaignStore::open(storePath, db::StoreAccess::ReadWrite, &error);
    if (!store) return error;
    const auto runId = db::runDbId(*store, campaignId, runName, &error);
    if (!runId || !db::flagRun(*store, *runId, {}, &error, redundant)) return error;
    return {};
}

QString keepFlags(const QString& storePath, const std::vector<qint64>& flagIds, bool kept) {
    QString error;
    auto store = db::CampaignStore::open(storePath, db::StoreAccess::ReadWrite, &error);
    if (!store || !db::setFlagsKept(*store, flagIds, kept, &error)) return error;
    return {};
}

}  // namespace driftlab::ui
