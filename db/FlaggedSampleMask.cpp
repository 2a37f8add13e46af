#include "db/FlaggedSampleMask.h"

#include <QJsonArray>

#include "db/SampleFlagStore.h"

namespace driftlab::db {

QString MaskedSamples::describe() const {
    QString text = QStringLiteral("%1 flagged samples of %2 channel(s) left out")
                       .arg(samples)
                       .arg(channels.size());
    // The first few by name: a noisy channel can have hundreds of spikes.
    constexpr int kNamed = 5;
    if (!stretches.isEmpty())
        text += QStringLiteral(": ") + stretches.mid(0, kNamed).join(QStringLiteral(", "));
    if (stretches.size() > kNamed)
        text += QStringLiteral(" and %1 more").arg(stretches.size() - kNamed);
    if (kept > 0) text += QStringLiteral("; %1 flagged stretch(es) kept").arg(kept);
    return text;
}

QJsonObject MaskedSamples::json() const {
    return {{QStringLiteral("samples"), qint64(samples)},
            {QStringLiteral("channels"), QJsonArray::fromStringList(channels)},
            {QStringLiteral("stretches"), QJsonArray::fromStringList(stretches)},
            {QStringLiteral("kept"), qint64(kept)}};
}

std::optional<MaskedSamples> leaveOutFlaggedSamples(CampaignStore& store, qint64 campaignId,
                                                    Campaign& campaign, QString* error) {
    const auto flags = loadStoredFlags(store, campaignId, error);
    if (!flags) return std::nullopt;
    MaskedSamples masked;
    masked.flagged = !flags->empty();
    for (Run& run : campaign.runs) {
        const auto found = flags->find(run.id);
        if (found == flags->end()) continue;
        std::vector<sensors::FlaggedRange> ranges;
        for (const StoredFlag& flag : found->second) {
            if (flag.kept) {
                ++masked.kept;
                continue;
            }
            ranges.push_back(flag.range);
            masked.stretches << QStringLiteral("%1 %2 %3 %4–%5 s")
                                    .arg(run.id, flag.range.channel,
                                         sensors::toString(flag.range.fault))
                                    .arg(flag.range.from_s)
                                    .arg(flag.range.to_s);
        }
        QStringList channels;
        masked.samples += sensors::maskFlaggedSamples(run, ranges, &channels);
        for (const QString& channel : channels)
            if (!masked.channels.contains(channel)) masked.channels << channel;
    }
    return masked;
}

}  // namespace driftlab::db
