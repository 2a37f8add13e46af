#pragma once
// The median of a set of readings: the zero of a temperature rise or a drift
// (robust to a spike in the first minute), a sampling interval, a benchmark's
// figure. The mean of the middle two for an even count; NaN for none.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace driftlab {

inline double median(std::vector<double> values) {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    if (values.size() % 2 == 1) return *middle;
    return 0.5 * (*middle + *std::max_element(values.begin(), middle));
}

}  // namespace driftlab
