#pragma once
// The engine of the exponential model:
//   E(x,t) = Σ_k e_k(t)·(a_k + b_k·(x − x_fixed))
// where e_k is the unit-gain first-order lag, time constant τ_k, of one
// heat-source input (without position dependence: E = Σ_k a_k·e_k(t)).
// Variable projection: for given τ the gains are a linear least squares, so
// only the τ are searched (log-spaced grid, then Ceres in log τ).

#include <Eigen/Core>
#include <QString>
#include <span>
#include <vector>

#include "core/models/FirstOrderLag.h"
#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

struct LagTerm {
    QString name;           ///< parameter prefix: "<name>.tau", "<name>.a", "<name>.b"
    std::size_t input = 0;  ///< which input of each case the term filters
    QString input_unit;     ///< e.g. "W", "rad/s"
};

struct LagSearchOptions {
    double min_tau_s = 60;
    double max_tau_s = 6 * 3600;
    int grid_points = 25;  ///< per time constant, log-spaced
};

/// One run: its inputs and the points where the model is evaluated.
struct LagCase {
    std::vector<PiecewiseInput> inputs;
    std::vector<double> time_s;
    Eigen::VectorXd dx;  ///< x − x_fixed of each point (unused without position dependence)
};

class LaggedRegression {
public:
    LaggedRegression(std::vector<LagTerm> terms, LagSearchOptions options);

    /// Fits the τ and gains to `observed` (one vector per case). Terms that
    /// filter the same input are returned in ascending τ. Throws ModelError.
    FitSummary fit(const std::vector<LagCase>& cases, const std::vector<Eigen::VectorXd>& observed,
                   bool positionDependent);
    Eigen::VectorXd predict(const LagCase& c) const;

private:
    /// Lag response of term k at the points of all cases, stacked.
    Eigen::VectorXd termResponse(std::span<const LagCase> cases, std::size_t k, double tau_s) const;
    /// Lag responses of every term (columns) at the points of all cases, stacked.
    Eigen::MatrixXd responses(std::span<const LagCase> cases,
                              const std::vector<double>& tau_s) const;
    Eigen::MatrixXd design(const Eigen::MatrixXd& responses, const Eigen::VectorXd& dx) const;
    /// The best τ on the log grid (terms on the same input in ascending order).
    std::vector<double> gridSearch(std::span<const LagCase> cases, const Eigen::VectorXd& dx,
                                   const Eigen::VectorXd& y) const;
    std::vector<double> sortedPerInput(std::vector<double> tau_s) const;
    /// The Jacobian of the fitted model in (log τ, gains), for the uncertainties.
    Eigen::MatrixXd jacobian(std::span<const LagCase> cases, const Eigen::MatrixXd& X,
                             const Eigen::VectorXd& dx) const;
    void validate(std::span<const LagCase> cases,
                  const std::vector<Eigen::VectorXd>& observed) const;

    std::vector<LagTerm> m_terms;
    LagSearchOptions m_options;
    bool m_position_dependent = true;
    std::vector<double> m_tau_s;
    Eigen::VectorXd m_gains;  ///< a_1..a_K, then b_1..b_K when position-dependent
};

}  // namespace driftlab::models
