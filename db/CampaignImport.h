#pragma once
// Bundles into the store: read, validated and stored in one streaming pass and
// one transaction, so memory does not grow with samples.csv and a bundle that
// fails anywhere (or is cancelled) leaves the store as it was.

#include <QString>
#include <QStringList>
#include <functional>
#include <optional>

#include "core/bundle/BundleSource.h"
#include "db/CampaignStore.h"

namespace driftlab::db {

struct BundleImportOptions {
    /// Fraction done (0..1); return false to cancel (nothing is stored).
    std::function<bool(double)> progress;
    /// Store the bundle even when the same content was imported before.
    bool again = false;
};

struct BundleImportResult {
    std::optional<qint64> campaignId;  ///< set when stored
    QString name;
    QStringList warnings;  ///< read but unusual ("file:line: ...")
    QString error;         ///< why nothing was stored; bundle errors as path:line:column: why
    std::optional<qint64> duplicateOf;  ///< the campaign already holding the same content
    QByteArray contentSha256;           ///< hex, of the bundle's files (see bundleContentSha256)
};

BundleImportResult importBundle(CampaignStore& store, const BundleSource& source,
                                const BundleImportOptions& options = {});

}  // namespace driftlab::db
