#pragma once
// Linear least squares with parameter uncertainties, shared by the models.

#include <Eigen/Core>

namespace driftlab::models {

struct LeastSquaresFit {
    Eigen::VectorXd coefficients;
    /// 1σ of each coefficient from the residual variance and (XᵀX)⁻¹; NaN when
    /// the data do not determine it (rank-deficient X or no degree of freedom).
    Eigen::VectorXd sigma;
    double rss = 0;  ///< residual sum of squares
    bool full_rank = false;
};

/// Solves min |X·c − y|² by column-pivoting QR on unit-norm columns (so that
/// ΔT⁴·x columns next to ΔT columns do not hide a rank deficiency).
LeastSquaresFit solveLeastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y);

/// 1σ of parameters from the Jacobian J of the model at the optimum and the
/// residual sum of squares: sqrt(diag(s²·(JᵀJ)⁻¹)), s² = rss/(n − p); NaN
/// where not determined.
Eigen::VectorXd parameterSigma(const Eigen::MatrixXd& J, double rss);

/// Features F and, for a position-dependent error, F·(x − x_fixed) beside them:
/// the design of E = Σ F_j·(a_j + b_j·(x − x_fixed)).
Eigen::MatrixXd withPositionGain(const Eigen::MatrixXd& F, const Eigen::VectorXd& dx);

/// Coefficient of determination 1 − rss/Σ(y − ȳ)².
double rSquared(double rss, const Eigen::VectorXd& y);

}  // namespace driftlab::models
