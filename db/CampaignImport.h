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

/// The first pass of an import, before the store is opened: the whole bundle
/// read and validated with its rows discarded as they go (memory stays flat),
/// and its content hash. A bad bundle is refused here, so a store it was meant
/// for is never opened for writing and stays byte for byte as it was.
struct BundleCheck {
    QString error;             ///< empty when the bundle is good; else "path:line:column: why"
    QString name;              ///< the campaign's name
    QStringList warnings;      ///< read but unusual ("file:line: ...")
    QByteArray contentSha256;  ///< hex, see bundleContentSha256
    bool ok() const { return error.isEmpty(); }
};
BundleCheck checkBundle(const bundle::BundleSource& source,
                        const std::function<bool(double)>& progress = {});

/// Why `store` must not take the checked bundle again: it already holds a
/// campaign imported from the same content (named with its id and date).
std::optional<QString> alreadyImported(CampaignStore& store, const bundle::BundleSource& source,
                                       const BundleCheck& checked);

struct BundleImportOptions {
    /// Fraction done (0..1); return false to cancel (nothing is stored).
    std::function<bool(double)> progress;
    /// Store the bundle even when the same content was imported before.
    bool again = false;
};

struct BundleImportResult {
    std::optional<qint64> campaignId;  ///< set when stored
    QString error;                     ///< why nothing was stored
};

/// The second pass: the checked bundle streamed into the store in one
/// transaction, refused when the store already holds its content (unless
/// `again`). On any failure the transaction is rolled back.
BundleImportResult importBundle(CampaignStore& store, const bundle::BundleSource& source,
                                const BundleCheck& checked,
                                const BundleImportOptions& options = {});

}  // namespace driftlab::db
