#pragma once
// What a late sensor saw. A sensor that follows what it measures through a
// first-order lag τ reads T_s with T = T_s + τ·dT_s/dt. The slope is that of a
// straight line through the readings within ±halfWindow_s: a difference of
// neighbouring readings would be all noise, and the room, the air and the
// structure change over tens of minutes to hours.

#include <vector>

namespace driftlab::diagnosis {

/// The readings with the lag τ undone; times need not be even. Fewer than 3
/// readings, or τ ≤ 0, come back unchanged.
std::vector<double> beforeTheLag(const std::vector<double>& time_s,
                                 const std::vector<double>& value, double tau_s,
                                 double halfWindow_s = 600);

}  // namespace driftlab::diagnosis
