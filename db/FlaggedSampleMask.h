#pragma once
// Flagged samples left out of a campaign before a model sees it: the samples
// `health --store` or the sensor-health page flagged become NaN (missing to
// every model), except those of a stretch the user kept. Shared by the CLI
// (unless --keep-flagged) and the GUI.

#include <QJsonObject>
#include <QStringList>
#include <optional>

#include "core/domain/Campaign.h"
#include "db/CampaignStore.h"

namespace driftlab::db {

struct MaskedSamples {
    bool flagged = false;     ///< the store holds flags for the campaign
    std::size_t samples = 0;  ///< sample values left out
    QStringList channels;     ///< the channels they belong to
    QStringList stretches;    ///< the stretches left out: "RUN CHANNEL KIND FROM–TO s"
    std::size_t kept = 0;     ///< flagged stretches kept: their samples are used
    /// "N flagged samples of M channel(s) left out: (the first five stretches)
    /// [and X more]; K flagged stretch(es) kept".
    QString describe() const;
    /// {"samples", "channels", "stretches", "kept"}: stored with a fit (its
    /// metrics' "flagged_left_out") so the fit names what it did not see.
    QJsonObject json() const;
};

/// Masks in `campaign` (campaign `campaignId` of `store`) the samples the store
/// flagged and the user did not keep (a sample also inside a kept stretch of
/// another kind is still left out); nullopt with `error` when the flags cannot be read.
std::optional<MaskedSamples> leaveOutFlaggedSamples(CampaignStore& store, qint64 campaignId,
                                                    Campaign& campaign, QString* error);

}  // namespace driftlab::db
