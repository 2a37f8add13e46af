#pragma once
// A value given at ascending points, read between them: linear between
// neighbours and held at the first and last beyond them (a table's correction,
// an interval by target position). Never extrapolated: beyond the measured
// points nothing says how the value goes on.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace driftlab {

/// `value` at `x`, given at the ascending `points` (as many, at least one).
inline double heldLinearAt(const std::vector<double>& points, const std::vector<double>& value,
                           double x) {
    if (x <= points.front()) return value.front();
    if (x >= points.back()) return value.back();
    const auto hi = std::size_t(std::upper_bound(points.begin(), points.end(), x) - points.begin());
    const double f = (x - points[hi - 1]) / (points[hi] - points[hi - 1]);
    return value[hi - 1] + f * (value[hi] - value[hi - 1]);
}

}  // namespace driftlab
