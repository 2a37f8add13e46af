#pragma once

#include <vector>

#include "core/models/ThermalErrorData.h"

namespace driftlab::models {

/// The mean of τ² over each step of a screw simulation: what the motor's
/// copper loss follows.
///
/// A drive logs its torque either as instantaneous samples or as an RMS over
/// the sample interval (I²t). Instantaneous samples a few seconds apart
/// cannot measure the mean of τ²: most of it comes from the inertia torque of
/// the speed changes, a few percent of the time, which a sample catches by
/// chance (on a 5 s log, ±30 % over a quarter of an hour). So the torque is
/// explained by the motion instead, as a drive engineer would:
///
///   τ = F_c·sgn ω + b·ω + J·α,
///   mean τ² over a step = F_c²·(moving fraction) + 2F_c·b·mean|ω| + b²·mean ω²
///                        + J²·(energy of the speed changes),
///
/// where a speed change Δω costs J²·α·|Δω| at a set acceleration and
/// J²·Δω²/t_acc in a set time; both are features. The coefficients are the
/// least-squares fit of the squared samples on the features of the steps
/// they fall in; the α·ω cross terms cancel over each start and stop. RMS
/// samples are spanned by the same features, but a log that never goes
/// negative is taken as an RMS and its squares are averaged over each step,
/// as they are without motion segments (motion taken from position samples has no speed
/// changes to speak of), or with fewer samples than features, the squared
/// samples are averaged over each step.
std::vector<double> meanTorqueSquaredPerStep(const RunData& run,
                                             const std::vector<MotionSegment>& motion,
                                             std::size_t steps, double dt_s);

}  // namespace driftlab::models
