#include "core/models/ModelledRuns.h"

namespace driftlab::models {

QStringList modelledRuns(const Campaign& campaign, const QString& targetChannel) {
    QStringList ids;
    for (const Run& run : campaign.runs) {
        if (targetChannel.isEmpty()
                ? isFeedAxisRun(run.kind) && !run.positioning.empty()
                : run.samples.columnIndex(targetChannel) >= 0 && !isFeedAxisRun(run.kind))
            ids << run.id;
    }
    return ids;
}

QStringList driftTargets(const Campaign& campaign) {
    QStringList targets;
    for (const Channel& channel : campaign.channels) {
        if (channel.quantity != Quantity::Displacement) continue;
        if (!modelledRuns(campaign, channel.id).isEmpty()) targets << channel.id;
    }
    return targets;
}

}  // namespace driftlab::models
