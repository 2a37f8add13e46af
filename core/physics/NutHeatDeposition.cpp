#include "core/physics/NutHeatDeposition.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace driftlab::physics {

namespace {

/// ½·max(u, 0)², branch-free: the sign changes from cell to cell along a stroke.
inline double halfSquaredRamp(double u) {
    u = std::max(u, 0.0);
    return 0.5 * u * u;
}

/// Antiderivative in x of |[x−w/2, x+w/2] ∩ [lo, hi]|.
inline double overlapAntiderivative(double x, double halfNut, double lo, double hi) {
    return halfSquaredRamp(x + halfNut - lo) - halfSquaredRamp(x + halfNut - hi) -
           halfSquaredRamp(x - halfNut - lo) + halfSquaredRamp(x - halfNut - hi);
}

}  // namespace

double depositNutHeat(std::vector<double>& energy_J, double cell_m, double nut_m, double from_m,
                      double to_m, double duration_s, double power_W) {
    if (power_W == 0 || duration_s <= 0) return 0;
    const double lo = std::min(from_m, to_m);
    const double hi = std::max(from_m, to_m);
    const double halfNut = 0.5 * nut_m;
    const auto cells = static_cast<long>(energy_J.size());
    const long first = std::max(0L, static_cast<long>(std::floor((lo - halfNut) / cell_m)));
    const long last = std::min(cells - 1, static_cast<long>(std::floor((hi + halfNut) / cell_m)));
    if (first > last) return 0;

    const double stroke = hi - lo;
    // A stroke shorter than a nanometre is a dwell: the time under the nut is
    // the whole duration times the overlap of nut and cell.
    const bool dwell = stroke < 1e-9;
    const double scale =
        dwell ? power_W * duration_s / nut_m : power_W * duration_s / (nut_m * stroke);
    double added = 0;
    auto add = [&](long i, double e) {
        energy_J[static_cast<std::size_t>(i)] += e;
        added += e;
    };
    if (dwell) {
        for (long i = first; i <= last; ++i) {
            const double a = i * cell_m;
            add(i, scale * std::max(0.0, std::min(a + cell_m, lo + halfNut) -
                                             std::max(a, lo - halfNut)));
        }
        return added;
    }
    // Cells [from, to): the overlap's integral over each, from its antiderivative.
    auto ramps = [&](long from, long to) {
        if (from >= to) return;
        double left = overlapAntiderivative(from * cell_m, halfNut, lo, hi);
        for (long i = from; i < to; ++i) {
            const double right = overlapAntiderivative(i * cell_m + cell_m, halfNut, lo, hi);
            add(i, scale * (right - left));
            left = right;
        }
    };
    // A cell between lo + w/2 and hi − w/2 sees the whole nut pass over it:
    // there the antiderivative is w·(x − lo), so each such cell takes w·cell
    // and the ramps are needed only where the stroke turns: on a long stroke,
    // a few of its cells.
    const long innerFirst = std::max(first, static_cast<long>(std::ceil((lo + halfNut) / cell_m)));
    const long innerEnd =
        std::min(last + 1, static_cast<long>(std::floor((hi - halfNut) / cell_m)));
    if (innerFirst >= innerEnd) {
        ramps(first, last + 1);
        return added;
    }
    ramps(first, innerFirst);
    const double inner = scale * nut_m * cell_m;
    for (long i = innerFirst; i < innerEnd; ++i) energy_J[static_cast<std::size_t>(i)] += inner;
    added += inner * double(innerEnd - innerFirst);
    ramps(innerEnd, last + 1);
    return added;
}

namespace {

/// The mean of |feed| over [t0, t1), each sample held until the next; NaN
/// when no sample reaches into the interval.
double meanAbsFeed(const std::vector<double>& time_s, const std::vector<double>& feed, double t0,
                   double t1) {
    auto k = std::upper_bound(time_s.begin(), time_s.end(), t0) - time_s.begin();
    if (k == 0) return std::nan("");
    double integral = 0;
    for (double from = t0; from < t1; ++k) {
        const double to = std::size_t(k) < time_s.size() ? std::min(t1, time_s[k]) : t1;
        integral += std::abs(feed[std::size_t(k) - 1]) * (to - from);
        from = to;
    }
    return integral / (t1 - t0);
}

/// The nut from x0 to x1 over [t0, t1] along a path of about `path_mm`,
/// stroking between lo and hi: to the nearer or the farther end first, then
/// n full strokes, then to x1, whichever of these comes nearest the path.
void appendStrokes(std::vector<MotionSegment>& motion, double t0, double t1, double x0, double x1,
                   double lo, double hi, double path_mm) {
    const double stroke = hi - lo;
    double bestMiss = std::numeric_limits<double>::infinity(), firstEnd = lo;
    int bestStrokes = 0;
    for (double end : {lo, hi}) {
        const double other = end == lo ? hi : lo;
        const double guess = (path_mm - std::abs(x0 - end)) / stroke;
        for (int n = std::max(0, int(guess) - 1); n <= std::max(0, int(guess) + 1); ++n) {
            const double last = n % 2 == 0 ? end : other;
            const double miss =
                std::abs(std::abs(x0 - end) + n * stroke + std::abs(last - x1) - path_mm);
            if (miss < bestMiss) bestMiss = miss, firstEnd = end, bestStrokes = n;
        }
    }
    std::vector<double> points{x0, firstEnd};
    for (int n = 0; n < bestStrokes; ++n) points.push_back(points.back() == lo ? hi : lo);
    points.push_back(x1);
    double length = 0;
    for (std::size_t i = 1; i < points.size(); ++i) length += std::abs(points[i] - points[i - 1]);
    const double speed_mm_s = length / (t1 - t0);
    double t = t0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const double leg = points[i] - points[i - 1];
        if (leg == 0) continue;
        const double end = std::min(t1, t + std::abs(leg) / speed_mm_s);
        motion.push_back({t, end, points[i - 1], points[i], std::copysign(speed_mm_s * 60, leg)});
        t = end;
    }
}

}  // namespace

std::vector<MotionSegment> motionFromPositionSamples(const std::vector<double>& time_s,
                                                     const std::vector<double>& position_mm,
                                                     const std::vector<double>& feedTime_s,
                                                     const std::vector<double>& feed_mm_min) {
    if (time_s.size() != position_mm.size() || feedTime_s.size() != feed_mm_min.size())
        throw std::invalid_argument("position samples: time and value differ in length");
    std::vector<MotionSegment> motion;
    motion.reserve(time_s.size());
    for (std::size_t i = 1; i < time_s.size(); ++i) {
        const double dt = time_s[i] - time_s[i - 1];
        if (!(dt > 0))
            throw std::invalid_argument("position samples: time does not increase at sample " +
                                        std::to_string(i));
        if (!std::isfinite(position_mm[i]) || !std::isfinite(position_mm[i - 1]))
            throw std::invalid_argument("position samples: missing position at sample " +
                                        std::to_string(std::isfinite(position_mm[i]) ? i - 1 : i));
        const double x0 = position_mm[i - 1], x1 = position_mm[i];
        const double path_mm =
            meanAbsFeed(feedTime_s, feed_mm_min, time_s[i - 1], time_s[i]) * dt / 60;
        const std::size_t first = i - 1 - std::min(i - 1, kStrokeWindow);
        const std::size_t last = std::min(time_s.size() - 1, i + kStrokeWindow);
        const auto [lo, hi] = std::minmax_element(position_mm.begin() + std::ptrdiff_t(first),
                                                  position_mm.begin() + std::ptrdiff_t(last) + 1);
        if (path_mm > 1.2 * std::abs(x1 - x0) && *hi - *lo > 1e-6)
            appendStrokes(motion, time_s[i - 1], time_s[i], x0, x1, *lo, *hi, path_mm);
        else
            motion.push_back({time_s[i - 1], time_s[i], x0, x1, (x1 - x0) / dt * 60});
    }
    return motion;
}

}  // namespace driftlab::physics
