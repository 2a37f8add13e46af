#pragma once
// Cross-validation for choosing a model's structure (sensors, degree) on the
// training runs only, so the held-out test runs stay untouched.

#include <Eigen/Core>
#include <vector>

#include "core/models/ThermalErrorData.h"

namespace driftlab::models {

/// The fold of each observation row (the runs' observations concatenated in
/// order): leave-one-run-out with several runs; with a single run, `timeBlocks`
/// contiguous blocks of its observations in time, so that a held-out block
/// tests extrapolation in time rather than interpolation between neighbours.
/// Throws ModelError for fewer than 2 blocks.
std::vector<int> crossValidationFolds(const std::vector<RunData>& runs, int timeBlocks = 5);

/// RMS of the held-out residuals over all folds; +infinity when the rows left
/// to fit in some fold cannot determine the coefficients.
double crossValidatedRms(const Eigen::MatrixXd& X, const Eigen::VectorXd& y,
                         const std::vector<int>& folds);

/// The same cross-validation for many subsets of one design's columns: each
/// fold's normal equations (XᵀX, Xᵀy) are summed once, so a subset costs a
/// k×k solve and its held-out residual per fold instead of a QR of the rows
/// the fold fits on. A best-subset
/// search over 16 sensors tries 696 subsets on tens of thousands of rows.
/// A subset whose normal equations are ill-conditioned (where squaring the
/// condition number loses digits) is scored by crossValidatedRms on its rows.
/// `X`, `y` and `folds` must outlive the object.
class FoldNormalEquations {
public:
    FoldNormalEquations(const Eigen::MatrixXd& X, const Eigen::VectorXd& y,
                        const std::vector<int>& folds);
    /// crossValidatedRms(X(:, columns), y, folds), to rounding.
    double crossValidatedRms(const std::vector<Eigen::Index>& columns) const;

private:
    const Eigen::MatrixXd& X_;
    const Eigen::VectorXd& y_;
    const std::vector<int>& m_folds;
    std::vector<Eigen::MatrixXd> m_heldOutX;  ///< per fold: its rows of X
    std::vector<Eigen::VectorXd> m_heldOutY;  ///< per fold: its rows of y
    std::vector<Eigen::MatrixXd> m_gram;      ///< per fold: X_fᵀX_f
    std::vector<Eigen::VectorXd> m_moment;    ///< per fold: X_fᵀy_f
    Eigen::MatrixXd m_totalGram;
    Eigen::VectorXd m_totalMoment;
};

/// Of candidates ordered simplest first, the simplest whose score is within
/// `tolerance` (2 %; or 1e-6 µm, far below any measurement) of the best: a more
/// complex model must earn its place. Returns scores.size() when no score is finite.
std::size_t simplestNearBest(const std::vector<double>& scores, double tolerance = 0.02);

}  // namespace driftlab::models
