#include "db/FlaggedSampleMask.h"

#include "db/SampleFlagStore.h"

namespace driftlab::db {

std::optional<MaskedSamples> leaveOutFlaggedSamples(CampaignStore& store, qint64 campaignId,
                                                    Campaign& campaign, QString* error) {
    const auto flags = loadSampleFlags(store, campaignId, error);
    if (!flags) return std::nullopt;
    MaskedSamples masked;
    masked.flagged = !flags->empty();
    for (Run& run : campaign.runs) {
        const auto found = flags->find(run.id);
        if (found == flags->end()) continue;
        QStringList channels;
        masked.samples += sensors::maskFlaggedSamples(run, found->second, &channels);
        for (const QString& channel : channels)
            if (!masked.channels.contains(channel)) masked.channels << channel;
    }
    return masked;
}

}  // namespace driftlab::db
