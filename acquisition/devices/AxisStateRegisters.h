#pragma once
// The axis state a controller reports in block 0 of DriftLab's register map
// (docs/modbus-register-map.md, registers 8…13): actual position int32 in
// 0.1 µm, feed int32 in 0.1 mm/min (signed: the direction of travel), motor
// torque int16 in 0.01 N·m, each 32-bit value high word first. Encoding
// rounds halves away from zero and saturates at the type's limits, as a
// controller's own conversion would.

#include <array>
#include <cstdint>
#include <span>

namespace driftlab::devices {

struct AxisState {
    double position_mm = 0;
    double feed_mm_min = 0;
    double torque_Nm = 0;
};

/// Register counts per unit: 0.1 µm, 0.1 mm/min, 0.01 N·m.
inline constexpr double kPositionCountsPerMm = 1e4;
inline constexpr double kFeedCountsPerMmMin = 10;
inline constexpr double kTorqueCountsPerNm = 100;

/// Registers 9…13: position (2), feed (2), torque (1); register 8 (the
/// report flag) is not part of it.
inline constexpr int kAxisStateRegisters = 5;
using AxisStateWords = std::array<std::uint16_t, kAxisStateRegisters>;

AxisStateWords encodeAxisState(const AxisState& state);
AxisState decodeAxisState(std::span<const std::uint16_t, kAxisStateRegisters> words);

}  // namespace driftlab::devices
