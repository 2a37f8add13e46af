#include "core/physics/NutHeatDeposition.h"

#include <algorithm>
#include <cmath>
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
    double previous = 0;
    for (long i = first; i <= last; ++i) {
        const double a = i * cell_m;
        const double b = a + cell_m;
        double covered;
        if (dwell) {
            covered = std::max(0.0, std::min(b, lo + halfNut) - std::max(a, lo - halfNut));
        } else {
            const double left = i == first ? overlapAntiderivative(a, halfNut, lo, hi) : previous;
            previous = overlapAntiderivative(b, halfNut, lo, hi);
            covered = previous - left;
        }
        const double e = scale * covered;
        energy_J[static_cast<std::size_t>(i)] += e;
        added += e;
    }
    return added;
}

std::vector<MotionSegment> motionFromPositionSamples(const std::vector<double>& time_s,
                                                     const std::vector<double>& position_mm) {
    if (time_s.size() != position_mm.size())
        throw std::invalid_argument("position samples: time and position differ in length");
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
        motion.push_back({time_s[i - 1], time_s[i], position_mm[i - 1], position_mm[i],
                          (position_mm[i] - position_mm[i - 1]) / dt * 60});
    }
    return motion;
}

}  // namespace driftlab::physics
