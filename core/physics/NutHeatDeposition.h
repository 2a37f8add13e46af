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

/// Motion segments through dense position samples (for example a controller
/// log at 10 Hz): the nut moves linearly from one sample to the next.
std::vector<MotionSegment> motionFromPositionSamples(const std::vector<double>& time_s,
                                                     const std::vector<double>& position_mm);

}  // namespace driftlab::physics
