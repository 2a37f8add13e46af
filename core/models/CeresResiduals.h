#pragma once
// A residual vector computed by a function of one parameter block, for
// Ceres' numerically differentiated cost functions. The models' residuals come
// from a whole simulation or a whole linear solve, so one block holds them all.

#include <ceres/dynamic_numeric_diff_cost_function.h>
#include <ceres/iteration_callback.h>

#include <functional>

namespace driftlab::models {

struct ResidualFunction {
    std::function<bool(const double* parameters, double* residuals)> evaluate;
    bool operator()(double const* const* parameters, double* residuals) const {
        return evaluate(parameters[0], residuals);
    }
};

/// A cost of `residuals` values over one block of `parameters` values, owned by the caller's
/// problem.
template <ceres::NumericDiffMethodType Method>
ceres::CostFunction* numericCost(std::function<bool(const double*, double*)> evaluate,
                                 int parameters, int residuals) {
    auto* cost = new ceres::DynamicNumericDiffCostFunction<ResidualFunction, Method>(
        new ResidualFunction{std::move(evaluate)});
    cost->AddParameterBlock(parameters);
    cost->SetNumResiduals(residuals);
    return cost;
}

/// Stops a Ceres solve between iterations when `cancelled` says so (the GUI's
/// Cancel); the solve then ends with termination type USER_FAILURE.
class CancelCallback : public ceres::IterationCallback {
public:
    explicit CancelCallback(std::function<bool()> cancelled) : m_cancelled(std::move(cancelled)) {}
    ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
        return m_cancelled && m_cancelled() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
    }

private:
    std::function<bool()> m_cancelled;
};

}  // namespace driftlab::models
