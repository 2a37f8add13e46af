#pragma once
// Sensor self-diagnosis of logged data (docs/sensor-health.md): the batch form
// of ChannelHealthChecker over a SampleSeries column, and the drift check of
// two redundant sensors (two channels declared to measure the same place).

#include <QString>
#include <map>
#include <optional>
#include <vector>

#include "core/domain/Channel.h"
#include "core/domain/Run.h"
#include "core/sensors/ChannelHealthChecker.h"
#include "core/sensors/SensorHealthSettings.h"

namespace driftlab::sensors {

/// Live drift check of a redundant pair, O(1) per sample. The pair's
/// difference minus its mean over the first redundant_baseline_s (the
/// calibration offset) is smoothed and compared with redundant_drift_limit_K.
/// Which of the two drifted cannot be told from two sensors: both are flagged.
class RedundantPairChecker {
public:
    /// Throws std::invalid_argument on invalid settings.
    explicit RedundantPairChecker(SensorHealthSettings settings);
    /// A sample of both channels; NaN (missing or already flagged) is skipped.
    /// Returns RedundantDrift or no flag.
    SensorFlags push(double time_s, double first, double second);
    /// The calibration offset (first − second) once the baseline is complete.
    std::optional<double> offset() const;
    /// The smoothed divergence after removing the offset, K.
    double divergence_K() const { return m_smoothed; }

private:
    SensorHealthSettings m_settings;
    std::optional<double> m_start_s;
    double m_sum = 0;
    std::size_t m_count = 0;
    bool m_baseline_done = false;
    std::optional<double> m_last_s;
    double m_smoothed = 0;
};

struct ChannelHealth {
    std::vector<SensorFlags> flags;  ///< one per row of the series
    ChannelHealthSummary summary;
};

/// Runs the single-channel checks that fit `channel` (applicableChecks) over
/// its column. Throws std::invalid_argument for a channel without a column or
/// invalid settings.
ChannelHealth checkColumn(const SampleSeries& series, const Channel& channel,
                          const SensorHealthSettings& settings);

/// Two channels at the same place (e.g. two Pt100 in one bearing housing).
struct RedundantPair {
    QString first;
    QString second;
};

/// The pair written "A=B" (channel ids, spaces around them ignored); nullopt
/// when `text` is not two non-empty ids joined by one '='.
std::optional<RedundantPair> parseRedundantPair(const QString& text);

/// Checks every declared channel present in the series, then every redundant
/// pair on the samples that passed the single-channel checks; the pair flags
/// are added to both channels. Keyed by channel id. Throws
/// std::invalid_argument for invalid settings or a pair naming a channel that
/// is not a temperature column of the series.
std::map<QString, ChannelHealth> checkRun(const SampleSeries& series,
                                          const std::vector<Channel>& channels,
                                          const std::vector<RedundantPair>& redundant,
                                          const SensorHealthSettings& settings);

/// The summary of a channel from its final flags.
ChannelHealthSummary summarise(const QString& channel, const std::vector<double>& time_s,
                               const std::vector<SensorFlags>& flags);

}  // namespace driftlab::sensors
