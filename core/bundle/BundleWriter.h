#pragma once
// Writes a campaign bundle folder that BundleReader reads back identically.

#include <QString>
#include <optional>

#include "core/bundle/BundleError.h"
#include "core/domain/Campaign.h"

namespace driftlab {

/// Writes campaign.json, samples.csv and, where the campaign has such data,
/// motion.csv and positioning.csv into `directory` (created if needed). Numbers
/// are written in their shortest exact form, so reading gives the same doubles.
std::optional<BundleError> writeBundle(const Campaign& campaign, const QString& directory);

}  // namespace driftlab
