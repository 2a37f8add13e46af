#include "core/models/DataGaps.h"

#include <algorithm>
#include <cmath>

#include "core/domain/Median.h"
#include "core/models/ModelError.h"
#include "core/models/ThermalErrorData.h"

namespace driftlab::models {
namespace {

/// The noise of a signal from its second differences, which a smooth course
/// (a warming screw, a move at constant speed) hardly touches: for white noise
/// of σ, v[i+1] − 2v[i] + v[i−1] has σ·√6; the median absolute value is robust
/// to the few that a reversal or a spike makes.
double noiseOf(const Signal& s) {
    if (s.value.size() < 3) return 0;
    std::vector<double> second(s.value.size() - 2);
    for (std::size_t i = 1; i + 1 < s.value.size(); ++i)
        second[i - 1] = std::abs(s.value[i + 1] - 2 * s.value[i] + s.value[i - 1]);
    return 1.4826 * median(std::move(second)) / std::sqrt(6.0);
}

/// The smallest step between two samples: the logger's resolution.
double resolutionOf(const Signal& s) {
    double step = std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < s.value.size(); ++i) {
        const double d = std::abs(s.value[i] - s.value[i - 1]);
        if (d > 0) step = std::min(step, d);
    }
    return std::isfinite(step) ? step : 0;
}

/// A straight line through samples [first, last) of a signal, by least squares.
struct Line {
    double at_s = 0, value = 0, slope = 0;  ///< value at at_s (the samples' mean time)
    double rms = 0;                         ///< of the samples about the line
    double operator()(double t) const { return value + slope * (t - at_s); }
};

Line lineThrough(const Signal& s, std::size_t first, std::size_t last) {
    Line line;
    const double n = double(last - first);
    for (std::size_t i = first; i < last; ++i) {
        line.at_s += s.time_s[i] / n;
        line.value += s.value[i] / n;
    }
    double stt = 0, stv = 0;
    for (std::size_t i = first; i < last; ++i) {
        stt += (s.time_s[i] - line.at_s) * (s.time_s[i] - line.at_s);
        stv += (s.time_s[i] - line.at_s) * (s.value[i] - line.value);
    }
    line.slope = stt > 0 ? stv / stt : 0;
    double squares = 0;
    for (std::size_t i = first; i < last; ++i)
        squares += std::pow(s.value[i] - line(s.time_s[i]), 2);
    line.rms = std::sqrt(squares / n);
    return line;
}

/// How far a straight bridge over the hole between samples i−1 and i may be
/// from the channel's course: each side's line (through the samples within one
/// hole length of it, at least three) carried to the hole's middle, against the
/// chord between them; and how well a line describes either side at all.
double bridgeError(const Signal& s, std::size_t i) {
    const double t0 = s.time_s[i - 1], t1 = s.time_s[i], length = t1 - t0;
    std::size_t before = i - 1;
    while (before > 0 && (t0 - s.time_s[before - 1] <= length || i - before < 3)) --before;
    std::size_t after = i + 1;
    while (after < s.time_s.size() && (s.time_s[after] - t1 <= length || after - i < 3)) ++after;
    if (i - before < 2 || after - i < 2) return std::numeric_limits<double>::infinity();
    const Line left = lineThrough(s, before, i), right = lineThrough(s, i, after);
    const double middle = 0.5 * (t0 + t1);
    const double chord = 0.5 * (left(t0) + right(t1));
    return std::max(
        {std::abs(left(middle) - chord), std::abs(right(middle) - chord), left.rms, right.rms});
}

}  // namespace

void judgeHoles(Signal& s, const QString& runId, double runEnd_s, const QString& unit, bool stepped,
                std::vector<DataGap>& gaps) {
    s.holes.clear();
    if (s.time_s.size() < 2 || !(s.sampling_s > 0)) return;
    const double holeLength_s = kHoleIntervals * s.sampling_s;
    // A smooth channel may be off by its noise, at least its logger's
    // resolution. A stepped one must run straight through (a standing axis,
    // one speed on both sides: the heat made in the hole is then known); its
    // smallest step is a change of speed, no resolution.
    double largest = 0;
    for (double v : s.value) largest = std::max(largest, std::abs(v));
    const double tolerance = stepped ? std::max(3 * noiseOf(s), 1e-6 * largest)
                                     : std::max(3 * noiseOf(s), resolutionOf(s));
    auto report = [&](double from, double to, double error, bool bridged, bool toEnd) {
        s.holes.push_back({from, to, bridged, toEnd});
        DataGap gap;
        gap.run_id = runId;
        gap.channel = s.name;
        gap.unit = unit;
        gap.from_s = from;
        gap.to_s = to;
        gap.bridged = bridged;
        gap.to_run_end = toEnd;
        gap.bridge_error = error;
        gap.tolerance = tolerance;
        gaps.push_back(gap);
    };
    constexpr double kNoBridge = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 1; i < s.time_s.size(); ++i) {
        if (s.time_s[i] - s.time_s[i - 1] <= holeLength_s) continue;
        const double error = bridgeError(s, i);
        report(s.time_s[i - 1], s.time_s[i], std::isfinite(error) ? error : kNoBridge,
               error <= tolerance, false);
    }
    // A channel that stops before the run does: nothing to bridge to.
    if (runEnd_s - s.time_s.back() > holeLength_s)
        report(s.time_s.back(), runEnd_s, kNoBridge, false, true);
}

void leaveOutHoles(RunData& run) {
    std::vector<ErrorObservation> kept;
    for (const ErrorObservation& o : run.observations) {
        bool inside = false;
        for (DataGap& g : run.gaps)
            if (!g.bridged && SignalHole{g.from_s, g.to_s, false, g.to_run_end}.holds(o.time_s)) {
                ++g.observations_left_out;
                inside = true;
            }
        if (!inside) kept.push_back(o);
    }
    if (kept.empty() && !run.observations.empty())
        throw ModelError(QStringLiteral("run '%1': every observation falls in a hole of the "
                                        "log that cannot be bridged (%2)")
                             .arg(run.run_id, gapLines(run.gaps).join(QStringLiteral("; "))));
    run.observations = std::move(kept);
}

std::vector<DataGap> gapsOf(const std::vector<RunData>& runs) {
    std::vector<DataGap> gaps;
    for (const RunData& run : runs) gaps.insert(gaps.end(), run.gaps.begin(), run.gaps.end());
    return gaps;
}

QStringList gapLines(const std::vector<DataGap>& gaps) {
    QStringList lines;
    int bridged = 0;
    double longest_s = 0;
    QStringList bridgedChannels;
    for (const DataGap& g : gaps) {
        const QString where =
            QStringLiteral("run '%1', %2, %3–%4 s")
                .arg(g.run_id, g.channel, messageNumber(g.from_s), messageNumber(g.to_s));
        if (g.bridged) {
            ++bridged;
            longest_s = std::max(longest_s, g.to_s - g.from_s);
            const QString id = g.run_id + QLatin1Char(':') + g.channel;
            if (!bridgedChannels.contains(id)) bridgedChannels << id;
            continue;
        }
        const QString leftOut = g.observations_left_out > 0
                                    ? QStringLiteral("%1 observation(s) not fitted or scored")
                                          .arg(g.observations_left_out)
                                    : QStringLiteral("no observation falls in it");
        lines << (std::isfinite(g.bridge_error)
                      ? QStringLiteral("hole in the log left out: %1 (a straight bridge could "
                                       "miss the channel's course by %2 %3, more than the %4 %3 "
                                       "its noise allows): %5")
                            .arg(where)
                            .arg(g.bridge_error, 0, 'g', 2)
                            .arg(g.unit)
                            .arg(g.tolerance, 0, 'g', 2)
                            .arg(leftOut)
                      : QStringLiteral("hole in the log left out: %1 (the channel stops before "
                                       "the run ends, nothing to bridge to): %2")
                            .arg(where, leftOut));
    }
    if (bridged > 0)
        lines << QStringLiteral(
                     "%1 hole(s) in the log bridged, where the channel changes slowly "
                     "against the hole (the longest %2 s): %3")
                     .arg(bridged)
                     .arg(messageNumber(longest_s))
                     .arg(bridgedChannels.join(QStringLiteral(", ")));
    return lines;
}

}  // namespace driftlab::models
