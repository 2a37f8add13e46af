#pragma once
// The heat-source activities that drive the lag models, as piecewise-constant
// inputs over a run: screw speed, spindle speed.

#include <QString>

#include "core/models/FirstOrderLag.h"
#include "core/models/ThermalErrorData.h"

namespace driftlab::models {

// Each throws ModelError naming the model, the run and the missing column when
// the run cannot give the input (a hole is held across: see bridgedValueAt).

/// Screw speed |ω| = 2π·|feed|/(60·lead), rad/s: from the motion segments when
/// the run has them (exact timing, dwells at zero), else from the feed samples.
PiecewiseInput screwSpeed(const RunData& run, const QString& model);

/// Spindle speed, rad/s, from the campaign's speed channel.
PiecewiseInput spindleSpeed(const RunData& run, const QString& model);

}  // namespace driftlab::models
