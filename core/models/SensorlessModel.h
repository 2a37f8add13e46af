#pragma once
// Sensorless model: the thermal error of a feed axis from its motor alone, no
// temperature channel. A physics-shaped regression (see docs/models.md for why
// not a neural network): the friction power P = |torque·ω| and the screw speed
// |ω| each pass through a first-order lag with a fitted time constant,
//   E(x,t) = Σ_{s∈{P,|ω|}} lag_s(t)·(a_s + b_s·(x − x_fixed)).
// The torque of the reversals' accelerations is not friction heat: it is
// separated with the motion programme first (DriveFriction.h), so a model
// fitted on a slow state holds on a fast one.

#include "core/models/LagModel.h"

namespace driftlab::models {

class SensorlessModel final : public LagModel {
public:
    /// `separateInertia` false reads the logged torque as friction throughout
    /// (what the model did before; kept to show the difference).
    explicit SensorlessModel(LagSearchOptions search = {}, bool separateInertia = true);
    QString name() const override { return QStringLiteral("sensorless"); }
    QString describe() const override;

protected:
    std::vector<PiecewiseInput> inputs(const RunData& run, double until_s) const override;
    QStringList inputSignals(const RunData& run) const override;
    FitSummary fitRuns(const std::vector<RunData>& training) override;

private:
    bool separate_inertia_ = true;
    double inertia_term_ = 0;  ///< J²/t_acc, N²·m²·s (DriveFriction.h)
};

}  // namespace driftlab::models
