#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/models/ThermalErrorData.h"

namespace driftlab::models {

// The mean of τ² over each step of a screw simulation: what the motor's
// copper loss follows.
//
// A drive logs its torque either as an RMS over the sample interval (its I²t
// channel; never negative) or as instantaneous samples (signed). The RMS
// already holds the mean of τ². Instantaneous samples a few seconds apart do
// not: most of τ² on short strokes is the inertia torque of the speed
// changes, a few percent of the time, which a sample catches by chance (on a
// 5 s log, ±30 % over a quarter of an hour, and 30 % over a whole run). So an
// instantaneous log is explained by the motion instead, as a drive engineer
// would, and the drive is identified over all the runs at once (one drive,
// one inertia):
//
//   1. while the speed holds (samples well inside segments of a second or
//      more), |τ| = F_c + b·|ω|, by least squares;
//   2. what the speed changes add to τ², J²·∫α² dt, with ∫α² dt per step
//      from the motion as Σ Δω²/d, Δω the change of the signed speed (a
//      reversal swings it by twice the speed), d the time it took (the
//      shorter of the two segments it joins), by least squares on the
//      squared samples.
//
// The α·ω cross terms cancel over each start and stop.

/// A signed torque log with motion segments to explain it; a log that never
/// goes negative is an RMS.
bool instantaneousTorqueLog(const RunData& run);

/// The drive of `runs` with a signed torque log and motion segments, or none
/// (no such run, or too few samples at held speed).
std::optional<DriveTorqueModel> identifyDriveTorque(std::span<const RunData> runs);

/// Per step of `dt_s`: from the run's drive model when it has one, else the
/// mean of the squared samples in the step (the interpolated square when it
/// has none).
std::vector<double> meanTorqueSquaredPerStep(const RunData& run,
                                             const std::vector<MotionSegment>& motion,
                                             std::size_t steps, double dt_s);

}  // namespace driftlab::models
