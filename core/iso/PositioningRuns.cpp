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

PositioningRunChoice choosePositioningRun(const Campaign& campaign, const QString& wanted) {
    PositioningRunChoice choice;
    QString id = wanted;
    if (id.isEmpty()) {
        const DefaultRun chosen = defaultPositioningRun(campaign);
        if (chosen.id.isEmpty()) {
            choice.usage = !chosen.choices.isEmpty();
            choice.error = choice.usage ? chosen.why + QStringLiteral(" with --run") : chosen.why;
            return choice;
        }
        id = chosen.id;
    }
    if (const Run* run = campaign.findRun(id)) {
        if (run->positioning.empty())
            choice.error = QStringLiteral("run %1 has no positioning readings").arg(id);
        else
            choice.run = run;
        return choice;
    }
    QStringList ids;
    for (const Run& run : campaign.runs) ids << run.id;
    choice.usage = true;
    choice.error = QStringLiteral("--run: no run '%1' in the campaign (runs: %2)")
                       .arg(id, ids.join(QStringLiteral(", ")));
    return choice;
}

}  // namespace driftlab::iso
