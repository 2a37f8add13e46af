#include "core/models/ModelledRuns.h"

#include <algorithm>

#include "core/domain/MessageText.h"

namespace driftlab::models {
namespace {

/// A feed-axis run's thermal error is its drift from the cold reference cycle
/// 0; an ISO 230-2 run measured warm (cycles from 1) has none to model.
bool hasColdReference(const Run& run) {
    return std::any_of(run.positioning.begin(), run.positioning.end(),
                       [](const PositioningMeasurement& m) { return m.cycle == 0; });
}

}  // namespace

QStringList modelledRuns(const Campaign& campaign, const QString& targetChannel) {
    QStringList ids;
    for (const Run& run : campaign.runs) {
        if (targetChannel.isEmpty()
                ? isFeedAxisRun(run.kind) && hasColdReference(run)
                : run.samples.columnIndex(targetChannel) >= 0 && !isFeedAxisRun(run.kind))
            ids << run.id;
    }
    return ids;
}

QString whyNoModelledRun(const Campaign& campaign, const QString& targetChannel) {
    if (!targetChannel.isEmpty())
        return QStringLiteral("no spindle or ETVE run logs the drift channel '%1'")
            .arg(targetChannel);
    QStringList warm;
    for (const Run& run : campaign.runs)
        if (isFeedAxisRun(run.kind) && !run.positioning.empty() && !hasColdReference(run))
            warm << run.id;
    if (warm.isEmpty()) return QStringLiteral("no feed-axis run has positioning readings to model");
    return QStringLiteral(
               "run(s) %1 have positioning readings but no cycle 0 (the cold "
               "reference): a thermal error is the drift from it")
        .arg(quotedList(warm));
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
