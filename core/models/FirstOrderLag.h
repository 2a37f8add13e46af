#pragma once
// First-order lag of a piecewise-constant heat-source input: the thermal
// response shape of the exponential model and the arx model's lagged inputs.

#include <Eigen/Core>
#include <vector>

namespace driftlab::models {

/// value[i] holds from time_s[i] until time_s[i+1] (the last one for ever);
/// the input is zero before time_s[0]. time_s ascending.
struct PiecewiseInput {
    std::vector<double> time_s;
    std::vector<double> value;
};

/// Response e(t) at the times `at_s` (any order) of de/dt = (u − e)/τ started
/// at rest, integrated exactly for the piecewise-constant input:
/// e(t) = e(t⁻) + (u − e(t⁻))·(1 − exp(−Δt/τ)).
Eigen::VectorXd lagResponse(const PiecewiseInput& input, double tau_s,
                            const std::vector<double>& at_s);

}  // namespace driftlab::models
