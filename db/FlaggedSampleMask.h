#pragma once
// Flagged samples left out of a campaign before a model sees it: the samples
// `health --store` flagged become NaN (missing to every model). Shared by the
// CLI (unless --keep-flagged) and the GUI.

#include <QStringList>
#include <optional>

#include "core/domain/Campaign.h"
#include "db/CampaignStore.h"

namespace driftlab::db {

struct MaskedSamples {
    bool flagged = false;     ///< the store holds flags for the campaign
    std::size_t samples = 0;  ///< sample values left out
    QStringList channels;     ///< the channels they belong to
};

/// Masks in `campaign` (campaign `campaignId` of `store`) the samples the store
/// flagged; nullopt with `error` when the flags cannot be read.
std::optional<MaskedSamples> leaveOutFlaggedSamples(CampaignStore& store, qint64 campaignId,
                                                    Campaign& campaign, QString* error);

}  // namespace driftlab::db
