#pragma once
// The nut as a moving heat source, deposited exactly: over one stroke at
// constant speed the nut covers a point x for |[x−w/2, x+w/2] ∩ [lo, hi]| / |v|
// seconds, so a cell receives Q/(w·|v|) times the integral of that overlap
// over the cell. The overlap is a trapezoid in x whose antiderivative is a sum
// of four half-squared ramps, so the cell energy is exact however far the nut
// travels within one time step (a fast stroke is not aliased by a coarse step).

#include <vector>

#include "core/domain/Run.h"

namespace driftlab::physics {

/// Adds to `energy_J` (one entry per cell of width `cell_m`, cell 0 starting
/// at x = 0) the heat of a nut of length `nut_m` moving at constant speed from
/// `from_m` to `to_m` (screw coordinates) with power `power_W` for
/// `duration_s`. Heat of the part of the nut beyond the screw is not added.
/// Returns the energy added, J. A stroke with from == to is a dwell: the nut
/// heats the cells under it for the whole duration.
double depositNutHeat(std::vector<double>& energy_J, double cell_m, double nut_m, double from_m,
                      double to_m, double duration_s, double power_W);

/// Motion segments through position samples: the nut moves linearly from one
/// sample to the next, as a dense log (a controller's at 10 Hz) shows it.
/// With the logged feed (`feedTime_s`, `feed_mm_min`, each sample held until
/// the next), a log too sparse to show the strokes is filled in: where the
/// feed covers more than 1.2× the distance between two position samples, the
/// nut strokes back and forth between the lowest and highest positions logged
/// within kStrokeWindow samples on either side, through both samples, over a
/// path as long as the feed says (to within one stroke). A logger reading
/// every 10 s sees a 2 s stroke as scattered points; the speed from their
/// differences would be a fraction of the real one, and so would the heat.
std::vector<MotionSegment> motionFromPositionSamples(const std::vector<double>& time_s,
                                                     const std::vector<double>& position_mm,
                                                     const std::vector<double>& feedTime_s = {},
                                                     const std::vector<double>& feed_mm_min = {});

/// Position samples on either side of an interval whose range bounds the
/// strokes filled in by motionFromPositionSamples.
constexpr std::size_t kStrokeWindow = 5;

}  // namespace driftlab::physics
