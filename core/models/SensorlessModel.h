#pragma once
// Sensorless model: the thermal error of a feed axis from its motor alone, no
// temperature channel. A physics-shaped regression (see docs/models.md for why
// not a neural network): the friction power P = |torque·ω| and the screw speed
// |ω| each pass through a first-order lag with a fitted time constant,
//   E(x,t) = Σ_{s∈{P,|ω|}} lag_s(t)·(a_s + b_s·(x − x_fixed)).

#include "core/models/LagModel.h"

namespace driftlab::models {

class SensorlessModel final : public LagModel {
public:
    explicit SensorlessModel(LagSearchOptions search = {});
    QString name() const override { return QStringLiteral("sensorless"); }
    QString describe() const override;

protected:
    std::vector<PiecewiseInput> inputs(const RunData& run, double until_s) const override;
    QStringList inputSignals(const RunData& run) const override;
};

}  // namespace driftlab::models
