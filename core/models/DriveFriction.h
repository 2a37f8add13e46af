#pragma once
// The friction heat a feed drive's torque shows, without the inertia torque of
// its reversals. Drives log the RMS torque over a sample interval (their
// thermal load), and at a reversal the motor also accelerates the screw and
// the table: J·Δω/t_acc for t_acc. That torque heats the motor, not the nut,
// and grows with the square of the speed change, so a model fitted at a slow
// state that reads it as friction overestimates the heat of a fast one.
//
// Per torque sample, over the interval since the previous one, the logged
// mean-square torque is friction while moving plus inertia at each change of
// speed (cross terms average out over the two directions):
//   τ² = A·f + B·⟨|ω|⟩ + C·⟨ω²⟩ + k·Σ(Δω)²/Δt,   k = J²/t_acc,
// with f the share of the interval spent moving and the speeds from the motion
// programme. k is fitted by linear least squares over the training runs; the
// friction torque of a sample is then √(τ² − k·Σ(Δω)²/Δt).

#include <QString>

#include "core/models/FirstOrderLag.h"
#include "core/models/ThermalErrorData.h"

namespace driftlab::models {

/// k = J²/t_acc in N²·m²·s, ≥ 0: 0 when the runs have no motion programme
/// (speed changes between samples are then unknown) or no torque.
double fitInertiaTerm(const std::vector<RunData>& runs);

/// Friction power |τ_friction·ω|, W, each torque sample's value held over the
/// interval it stands for, with ω from the motion programme; with
/// `inertiaTerm` 0 or no programme, the logged torque as it is times
/// `screwSpeed` (the held feed, screwSpeedFromFeed). Throws ModelError naming
/// `model` and the run when the torque is missing.
PiecewiseInput frictionPower(const RunData& run, const PiecewiseInput& screwSpeed, double until_s,
                             double inertiaTerm, const QString& model);

}  // namespace driftlab::models
