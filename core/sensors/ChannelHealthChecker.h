#pragma once
// Live self-diagnosis of one channel, sample by sample. Out of range and
// frozen are known when a sample arrives; a spike needs the samples after it
// (the Hampel window is centred), so a sample's verdict becomes final
// spike_half_window_samples later. A frozen stretch is only recognised once it
// has lasted frozen_window_s: its earlier, already final samples are then
// reported again as a backfill.

#include <QString>
#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

#include "core/domain/Channel.h"
#include "core/sensors/SensorHealthSettings.h"

namespace driftlab::sensors {

struct SampleVerdict {
    std::size_t index = 0;  ///< 0-based, in push order
    double time_s = 0;
    SensorFlags flags = kNoFlags;
};

/// Samples first_index…last_index (inclusive), already reported, are Frozen too.
struct FrozenBackfill {
    std::size_t first_index = 0;
    std::size_t last_index = 0;
    double from_s = 0;
    double to_s = 0;
};

struct HealthUpdate {
    std::vector<SampleVerdict> verdicts;  ///< samples that became final, in order
    std::optional<FrozenBackfill> backfill;
};

struct TimeRange {
    double from_s = 0;
    double to_s = 0;
};

/// What was found of one kind on one channel.
struct FaultFinding {
    SensorFault fault = SensorFault::OutOfRange;
    std::size_t samples = 0;
    std::vector<TimeRange> ranges;  ///< consecutive flagged samples form one range
};

struct ChannelHealthSummary {
    QString channel;
    std::size_t samples = 0;             ///< samples checked (missing ones included)
    std::vector<FaultFinding> findings;  ///< only kinds that were found, in bit order

    bool healthy() const { return findings.empty(); }
    const FaultFinding* finding(SensorFault fault) const;
    /// One line per finding, e.g. "T_nut: spike, 3 samples, 600–600 s, …".
    QString describe() const;
};

/// Builds a summary from verdicts in index order (and backfills), O(1) per sample.
class SummaryBuilder {
public:
    explicit SummaryBuilder(QString channel);
    void add(const SampleVerdict& verdict);
    void addBackfill(const FrozenBackfill& backfill);
    void addMissing() { ++m_samples; }
    ChannelHealthSummary summary() const;

private:
    struct Track {
        std::size_t samples = 0;
        std::vector<TimeRange> ranges;
        std::optional<std::size_t> last_index;
    };
    void mark(Track& track, std::size_t index, double time_s);
    QString m_channel;
    std::size_t m_samples = 0;
    Track m_tracks[std::size(kAllSensorFaults)];
};

/// Which single-channel checks fit a channel: out of range for every
/// quantity; frozen for temperatures (a drift probe or a speed may rightly
/// stand still); spike and rate of change for temperatures of parts that stay
/// put. The nut sensor rides over a screw whose temperature varies by several
/// kelvin along the stroke, so its reading rightly jumps by kelvins between
/// two samples (up to 3.9 K in 10 s on the simulated rig when the nut goes to
/// a measuring target): no spike or rate check for ChannelRole::Nut.
SensorFlags applicableChecks(Quantity quantity, ChannelRole role);

/// The single-channel checks, sample by sample. Memory and work per sample
/// are O(spike window).
class ChannelHealthChecker {
public:
    /// `checks`: the kinds to look for (applicableChecks; RedundantDrift is
    /// ignored here). `settings` must be valid (SensorHealthSettings::isValid);
    /// throws std::invalid_argument otherwise.
    ChannelHealthChecker(QString channel, Quantity quantity, SensorFlags checks,
                         SensorHealthSettings settings);

    /// A new sample, in increasing time; NaN is a missing sample (no verdict flags).
    HealthUpdate push(double time_s, double value);
    /// End of the data: the pending samples become final.
    HealthUpdate finish();
    /// Summary of every verdict returned so far.
    ChannelHealthSummary summary() const { return m_summary.summary(); }

private:
    struct Pending {
        std::size_t index;
        double time_s;
        double value;
        SensorFlags flags;
    };
    void checkFrozen(Pending& sample, HealthUpdate& update);
    SampleVerdict finalise(std::size_t position);
    void record(HealthUpdate& update);
    bool isSpike(std::size_t position) const;

    SensorHealthSettings m_settings;
    Quantity m_quantity;
    SensorFlags m_checks;
    std::size_t m_next_index = 0;
    // The last 2h+1 samples: positions < m_finalised are final (kept for the
    // window), the rest wait for their future half window.
    std::deque<Pending> m_window;
    std::size_t m_finalised = 0;
    // Frozen stretch: samples since `start` stay within the tolerance.
    struct Stretch {
        std::size_t start_index = 0;
        double start_s = 0;
        double min = 0;
        double max = 0;
        bool frozen = false;
        std::optional<std::pair<double, double>> before;  ///< last sample before it (t, value)
    };
    std::optional<Stretch> m_stretch;
    std::optional<std::pair<double, double>> m_last_in_range;
    // Rate reference: the last final sample without a fault, (t, value).
    std::optional<std::pair<double, double>> m_rate_reference;
    SummaryBuilder m_summary;
};

}  // namespace driftlab::sensors
