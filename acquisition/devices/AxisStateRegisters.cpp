#include "acquisition/devices/AxisStateRegisters.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "acquisition/push/CompensationRegisterMap.h"

namespace driftlab::devices {
namespace {

/// value × counts per unit, rounded half away from zero (std::round),
/// saturated to [lowest, highest]; NaN gives 0.
template <class Int>
Int counts(double value, double counts_per_unit) {
    const double n = std::round(value * counts_per_unit);
    if (std::isnan(n)) return 0;
    return Int(std::clamp(n, double(std::numeric_limits<Int>::lowest()),
                          double(std::numeric_limits<Int>::max())));
}

}  // namespace

AxisStateWords encodeAxisState(const AxisState& state) {
    AxisStateWords words{};
    push::putInt32(counts<std::int32_t>(state.position_mm, kPositionCountsPerMm), &words[0]);
    push::putInt32(counts<std::int32_t>(state.feed_mm_min, kFeedCountsPerMmMin), &words[2]);
    words[4] = std::uint16_t(counts<std::int16_t>(state.torque_Nm, kTorqueCountsPerNm));
    return words;
}

AxisState decodeAxisState(std::span<const std::uint16_t, kAxisStateRegisters> words) {
    AxisState state;
    // Dividing by the counts per unit (not multiplying by a step such as 0.1)
    // gives the double nearest the decimal value: 3 counts are 0.3 mm/min.
    state.position_mm = push::getInt32(&words[0]) / kPositionCountsPerMm;
    state.feed_mm_min = push::getInt32(&words[2]) / kFeedCountsPerMmMin;
    state.torque_Nm = std::int16_t(words[4]) / kTorqueCountsPerNm;
    return state;
}

}  // namespace driftlab::devices
