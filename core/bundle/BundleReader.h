#pragma once
// Reads a campaign bundle folder (DESIGN.md section 2): campaign.json,
// samples.csv, and the optional motion.csv and positioning.csv.

#include <QString>
#include <QStringList>
#include <functional>
#include <optional>

#include "core/bundle/BundleError.h"
#include "core/domain/Campaign.h"

namespace driftlab {

struct BundleReadOptions {
    /// Called with the fraction done (0..1); return false to cancel.
    std::function<bool(double fraction)> progress;
};

struct BundleReadResult {
    std::optional<Campaign> campaign;
    std::optional<BundleError> error;  ///< set when nothing could be read
    QStringList warnings;              ///< things that were read but look odd
    bool ok() const { return campaign.has_value(); }
};

/// Reads and validates a whole bundle. Either everything is read or the first
/// error is returned (file, line, column and why); nothing half-read escapes.
BundleReadResult readBundle(const QString& directory, const BundleReadOptions& options = {});

}  // namespace driftlab
