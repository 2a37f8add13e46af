#include "core/sensors/ChannelHealthChecker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace driftlab::sensors {
namespace {

// Scale of the MAD to the standard deviation of normal noise.
constexpr double kMadToSigma = 1.4826;
// Readings are decimal numbers: 20.07 − 20.06 is not exactly 0.01.
constexpr double kRoundingSlack = 1e-9;

// In place (core/domain/Median.h copies): it runs on every reading of a live
// window, and the caller reuses the buffer.
double medianInPlace(std::vector<double>& values) {
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    const double upper = *middle;
    if (values.size() % 2 == 1) return upper;
    const double lower = *std::max_element(values.begin(), middle);
    return 0.5 * (lower + upper);
}

std::size_t faultSlot(SensorFault fault) {
    std::size_t slot = 0;
    while (slot < std::size(kAllSensorFaults) && kAllSensorFaults[slot] != fault) ++slot;
    return slot;
}

}  // namespace

const FaultFinding* ChannelHealthSummary::finding(SensorFault fault) const {
    for (const auto& f : findings)
        if (f.fault == fault) return &f;
    return nullptr;
}

QString ChannelHealthSummary::describe() const {
    if (findings.empty())
        return QStringLiteral("%1: no fault in %2 samples").arg(channel).arg(samples);
    QStringList lines;
    for (const auto& f : findings) {
        QStringList ranges;
        for (const auto& r : f.ranges)
            ranges << QStringLiteral("%1–%2 s").arg(r.from_s, 0, 'f', 1).arg(r.to_s, 0, 'f', 1);
        lines << QStringLiteral("%1: %2, %3 samples: %4")
                     .arg(channel, toString(f.fault))
                     .arg(f.samples)
                     .arg(ranges.join(QStringLiteral(", ")));
    }
    return lines.join(QLatin1Char('\n'));
}

SummaryBuilder::SummaryBuilder(QString channel) : m_channel(std::move(channel)) {}

void SummaryBuilder::mark(Track& track, std::size_t index, double time_s) {
    ++track.samples;
    if (track.last_index && *track.last_index + 1 == index && !track.ranges.empty())
        track.ranges.back().to_s = time_s;
    else
        track.ranges.push_back({time_s, time_s});
    track.last_index = index;
}

void SummaryBuilder::add(const SampleVerdict& verdict) {
    ++m_samples;
    for (std::size_t slot = 0; slot < std::size(kAllSensorFaults); ++slot)
        if (has(verdict.flags, kAllSensorFaults[slot]))
            mark(m_tracks[slot], verdict.index, verdict.time_s);
}

void SummaryBuilder::addBackfill(const FrozenBackfill& backfill) {
    Track& track = m_tracks[faultSlot(SensorFault::Frozen)];
    track.samples += backfill.last_index - backfill.first_index + 1;
    if (track.last_index && *track.last_index + 1 == backfill.first_index && !track.ranges.empty())
        track.ranges.back().to_s = backfill.to_s;
    else
        track.ranges.push_back({backfill.from_s, backfill.to_s});
    track.last_index = backfill.last_index;
}

ChannelHealthSummary SummaryBuilder::summary() const {
    ChannelHealthSummary s;
    s.channel = m_channel;
    s.samples = m_samples;
    for (std::size_t slot = 0; slot < std::size(kAllSensorFaults); ++slot)
        if (m_tracks[slot].samples > 0)
            s.findings.push_back(
                {kAllSensorFaults[slot], m_tracks[slot].samples, m_tracks[slot].ranges});
    return s;
}

SensorFlags applicableChecks(Quantity quantity, ChannelRole role) {
    if (quantity != Quantity::Temperature) return bit(SensorFault::OutOfRange);
    const SensorFlags staticChecks = bit(SensorFault::OutOfRange) | bit(SensorFault::Frozen);
    if (role == ChannelRole::Nut) return staticChecks;
    return staticChecks | bit(SensorFault::Spike) | bit(SensorFault::RateOfChange);
}

ChannelHealthChecker::ChannelHealthChecker(QString channel, Quantity quantity, SensorFlags checks,
                                           SensorHealthSettings settings)
    : m_settings(settings), m_quantity(quantity), m_checks(checks), m_summary(std::move(channel)) {
    QString error;
    if (!m_settings.isValid(&error)) throw std::invalid_argument(error.toStdString());
}

HealthUpdate ChannelHealthChecker::push(double time_s, double value) {
    HealthUpdate update;
    Pending sample{m_next_index++, time_s, value, kNoFlags};
    if (has(m_checks, SensorFault::OutOfRange) && outOfRange(m_settings, m_quantity, value)) {
        sample.flags |= bit(SensorFault::OutOfRange);
        // A stuck overflow value is an open element, not a frozen one.
        m_stretch.reset();
    } else if (std::isfinite(value) && has(m_checks, SensorFault::Frozen)) {
        checkFrozen(sample, update);
        m_last_in_range = std::make_pair(time_s, value);
    }
    m_window.push_back(sample);
    const auto half = static_cast<std::size_t>(m_settings.spike_half_window_samples);
    while (m_finalised < m_window.size() && m_window.size() - 1 - m_finalised >= half) {
        update.verdicts.push_back(finalise(m_finalised));
        ++m_finalised;
    }
    record(update);
    return update;
}

HealthUpdate ChannelHealthChecker::finish() {
    HealthUpdate update;
    while (m_finalised < m_window.size()) {
        update.verdicts.push_back(finalise(m_finalised));
        ++m_finalised;
    }
    record(update);
    return update;
}

void ChannelHealthChecker::record(HealthUpdate& update) {
    for (const auto& v : update.verdicts) m_summary.add(v);
    // Only the past half window is needed for the spike median.
    const auto half = static_cast<std::size_t>(m_settings.spike_half_window_samples);
    while (m_finalised > half) {
        m_window.pop_front();
        --m_finalised;
    }
}

void ChannelHealthChecker::checkFrozen(Pending& sample, HealthUpdate& update) {
    const double v = sample.value;
    if (m_stretch) {
        const double lo = std::min(m_stretch->min, v);
        const double hi = std::max(m_stretch->max, v);
        if (hi - lo <= m_settings.frozen_tolerance_K + kRoundingSlack) {
            m_stretch->min = lo;
            m_stretch->max = hi;
        } else {
            m_stretch.reset();
        }
    }
    if (!m_stretch) {
        m_stretch = Stretch{sample.index, sample.time_s, v, v, false, m_last_in_range};
        return;
    }
    if (m_stretch->frozen) {
        sample.flags |= bit(SensorFault::Frozen);
        return;
    }
    // A few slow samples inside one quantisation step are not evidence: a
    // noisy sensor read every minute does that now and then.
    if (sample.time_s - m_stretch->start_s < m_settings.frozen_window_s ||
        sample.index - m_stretch->start_index + 1 < std::size_t(m_settings.frozen_min_samples))
        return;
    m_stretch->frozen = true;
    sample.flags |= bit(SensorFault::Frozen);
    for (auto& w : m_window)
        if (w.index >= m_stretch->start_index) w.flags |= bit(SensorFault::Frozen);
    // Samples of the stretch that were already final are reported again.
    const std::size_t pending = m_window.size() - m_finalised;
    const std::size_t emitted = sample.index - pending;  // samples 0…emitted−1 are final
    if (emitted > m_stretch->start_index) {
        const double lastEmitted_s = m_finalised > 0 ? m_window[m_finalised - 1].time_s : 0;
        update.backfill =
            FrozenBackfill{m_stretch->start_index, emitted - 1, m_stretch->start_s, lastEmitted_s};
        m_summary.addBackfill(*update.backfill);
    }
    // The rate of change after the stretch is judged against the sample before it.
    m_rate_reference = m_stretch->before;
}

bool ChannelHealthChecker::isSpike(std::size_t position) const {
    const auto half = static_cast<std::size_t>(m_settings.spike_half_window_samples);
    const std::size_t from = position >= half ? position - half : 0;
    const std::size_t to = std::min(m_window.size(), position + half + 1);
    std::vector<double> values;
    values.reserve(to - from);
    for (std::size_t i = from; i < to; ++i)
        if (std::isfinite(m_window[i].value) && !has(m_window[i].flags, SensorFault::OutOfRange))
            values.push_back(m_window[i].value);
    // With fewer than half a window of readings the median says nothing.
    if (values.size() < half + 1) return false;
    const double centre = medianInPlace(values);
    for (double& v : values) v = std::abs(v - centre);
    const double sigma = kMadToSigma * medianInPlace(values);
    const double threshold =
        std::max(m_settings.spike_mad_factor * sigma, m_settings.spike_min_deviation_K);
    return std::abs(m_window[position].value - centre) > threshold;
}

SampleVerdict ChannelHealthChecker::finalise(std::size_t position) {
    Pending& s = m_window[position];
    const bool reading = std::isfinite(s.value) && !has(s.flags, SensorFault::OutOfRange);
    if (reading && has(m_checks, SensorFault::Spike) && isSpike(position))
        s.flags |= bit(SensorFault::Spike);
    if (reading && !has(s.flags, SensorFault::Spike) && !has(s.flags, SensorFault::Frozen)) {
        if (m_rate_reference && has(m_checks, SensorFault::RateOfChange)) {
            const auto [t0, v0] = *m_rate_reference;
            const double allowed = m_settings.max_rate_K_per_s * std::max(0.0, s.time_s - t0) +
                                   m_settings.rate_noise_allowance_K;
            if (std::abs(s.value - v0) > allowed) s.flags |= bit(SensorFault::RateOfChange);
        }
        // A step too fast is flagged once; the new level is then the reference.
        m_rate_reference = std::make_pair(s.time_s, s.value);
    }
    return {s.index, s.time_s, s.flags};
}

}  // namespace driftlab::sensors
