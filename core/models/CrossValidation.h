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

/// Of candidates ordered simplest first, the simplest whose score is within
/// `tolerance` (2 %; or 1e-6 µm, far below any measurement) of the best: a more
/// complex model must earn its place. Returns scores.size() when no score is finite.
std::size_t simplestNearBest(const std::vector<double>& scores, double tolerance = 0.02);

}  // namespace driftlab::models
