#pragma once
// Reads a campaign bundle (docs/bundles.md) from a folder or, through
// db/ZipBundleSource, a zip archive: campaign.json, samples.csv, and the
// optional motion.csv and positioning.csv.

#include <QString>
#include <QStringList>
#include <functional>
#include <optional>

#include "core/bundle/BundleError.h"
#include "core/bundle/BundleSource.h"
#include "core/domain/Campaign.h"

namespace driftlab::bundle {

/// Receives samples.csv row by row instead of the campaign keeping them, so an
/// import streams into the store and memory does not grow with the file.
class SampleRowSink {
public:
    virtual ~SampleRowSink() = default;
    /// campaign.json has been read: metadata, channels, runs without data, and
    /// `sample_columns` in samples.csv order. Called once, before any row.
    virtual void begin(const Campaign& campaign) = 0;
    /// One row of run `runIndex`: values in `sample_columns` order, NaN = missing.
    /// Rows of a run arrive in increasing time.
    virtual void row(std::size_t runIndex, double time_s, const double* values) = 0;
};

struct BundleReadOptions {
    /// Called with the fraction done (0..1); return false to cancel.
    std::function<bool(double fraction)> progress;
    /// When set, samples go to the sink and the campaign's runs hold none.
    SampleRowSink* sampleSink = nullptr;
};

struct BundleReadResult {
    std::optional<Campaign> campaign;
    std::optional<BundleError> error;  ///< set when nothing could be read
    QStringList warnings;              ///< things that were read but look odd
    bool ok() const { return campaign.has_value(); }
};

/// Reads and validates a whole bundle. Either everything is read or the first
/// error is returned (file, line, column and why); nothing half-read escapes.
BundleReadResult readBundle(const BundleSource& source, const BundleReadOptions& options = {});
/// The same for a bundle folder.
BundleReadResult readBundle(const QString& directory, const BundleReadOptions& options = {});

}  // namespace driftlab::bundle
