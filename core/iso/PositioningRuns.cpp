#include "core/iso/PositioningRuns.h"

namespace driftlab::iso {

QStringList runsWithPositioning(const Campaign& campaign) {
    QStringList ids;
    for (const Run& run : campaign.runs)
        if (!run.positioning.empty()) ids << run.id;
    return ids;
}

DefaultRun defaultPositioningRun(const Campaign& campaign) {
    QStringList positioning, withReadings;
    for (const Run& run : campaign.runs) {
        if (run.positioning.empty()) continue;
        withReadings << run.id;
        if (run.kind == RunKind::Positioning) positioning << run.id;
    }
    DefaultRun result;
    const QStringList& candidates = positioning.isEmpty() ? withReadings : positioning;
    if (candidates.size() == 1)
        result.id = candidates.front();
    else if (candidates.isEmpty())
        result.why = QStringLiteral("no run of the campaign has positioning readings");
    else {
        result.choices = candidates;
        result.why = QStringLiteral("runs %1 have positioning readings: choose one")
                         .arg(candidates.join(QStringLiteral(", ")));
    }
    return result;
}

}  // namespace driftlab::iso
