#pragma once
// Exponential (variable-separation) model: each heat source k contributes a
// first-order exponential rise while it works and a decay while it rests,
//   e_k(t) = e_k(t⁻) + (u(t) − e_k(t⁻))·(1 − exp(−Δt/τ_k)),
//   E(x,t) = Σ_k e_k(t)·(a_k + b_k·(x − x_fixed))   (drift channel: Σ_k a_k·e_k(t)),
// with u the source activity: screw speed |ω| for a feed axis (from the motion
// programme, else the feed samples), spindle speed for a drift channel. The
// sources ("source1" fastest, …) differ by time constant and position shape,
// e.g. the screw under the nut (fast) and the bearing housing (slow).

#include "core/models/LagModel.h"

namespace driftlab::models {

struct ExponentialOptions {
    int sources = 2;  ///< 1 to 3
    LagSearchOptions search;
};

class ExponentialModel final : public LagModel {
public:
    explicit ExponentialModel(ExponentialOptions options = {});
    QString name() const override { return QStringLiteral("exponential"); }
    QString describe() const override;

protected:
    std::vector<PiecewiseInput> inputs(const RunData& run) const override;
    QStringList inputSignals(const RunData& run) const override;

private:
    int m_sources;
};

}  // namespace driftlab::models
