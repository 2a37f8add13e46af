#pragma once
// Derivative-free minimisation for the few nonlinear parameters of the lag
// models (time constants), whose objective is itself a linear least squares.

#include <Eigen/Core>
#include <functional>

namespace driftlab::models {

struct NelderMeadOptions {
    double initial_step = 0.5;  ///< size of the starting simplex along each axis
    double x_tolerance = 1e-7;  ///< stop when the simplex is this small in every axis
    int max_iterations = 2000;
};

struct NelderMeadResult {
    Eigen::VectorXd x;
    double value = 0;
    int iterations = 0;
    bool converged = false;  ///< the simplex shrank below x_tolerance
};

/// Minimises f from x0 with the standard Nelder–Mead simplex (reflection 1,
/// expansion 2, contraction ½, shrink ½). Deterministic.
NelderMeadResult minimiseNelderMead(const std::function<double(const Eigen::VectorXd&)>& f,
                                    const Eigen::VectorXd& x0,
                                    const NelderMeadOptions& options = {});

}  // namespace driftlab::models
