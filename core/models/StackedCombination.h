#pragma once
// `auto`'s combination of the model families: a stacked regression (Wolpert
// 1992, "Stacked generalization"; Breiman 1996, "Stacked regressions"). Each
// family's cross-validated predictions over the training runs' folds are the
// columns of P (readings × families); the weights w ≥ 0 with Σw = 1 minimise
// ‖P·w − y‖² against the measured errors y. The weights are a convex
// combination, so the stack predicts within the range of its members and can
// neither extrapolate a difference between two families nor amplify one; a
// family the others already give takes no weight. Since every single family
// is a vertex of that simplex, the stack's cross-validated RMS is never above
// the best family's. chooseCombination weighs the stack against the simpler
// equal-weight mean of the near-best families and keeps the no-harm guard.

#include <Eigen/Core>
#include <vector>

#include "core/models/ModelValidation.h"

namespace driftlab::models {

/// The weights w ≥ 0, Σw = 1 minimising ‖P·w − y‖², exactly, by an active-set
/// method (Lawson & Hanson 1974, ch. 23, with the sum constraint) on the F×F
/// Gram matrix PᵀP: starting from the best single column, a column joins only
/// where it lowers the squared error, so a copy of a column already in stays
/// at zero. P has at least one column.
Eigen::VectorXd stackingWeights(const Eigen::MatrixXd& P, const Eigen::VectorXd& y);

/// The families' predictions weighted: Σ w_f·predicted_f on the same readings.
HeldOutPredictions weightedPredictions(const std::vector<HeldOutPredictions>& families,
                                       const std::vector<double>& weights);

/// What `auto` predicts with, from each family's held-out predictions on the
/// same readings (families that could not be cross-validated left out).
struct CombinationChoice {
    enum class Kind {
        Stacked,     ///< the stacked combination
        Mean,        ///< the equal-weight mean of the near-best families
        BestSingle,  ///< the best family alone, where neither does better than none
        None         ///< no compensation: nothing does better than predicting zero
    };
    Kind kind = Kind::None;
    std::vector<std::size_t> members;  ///< indices into the families, heaviest first
    std::vector<double> weights;       ///< the members', summing to one
    /// The choice's held-out predictions (zero for no compensation).
    HeldOutPredictions predictions;
    /// The stack's weights over all the families and its cross-validated
    /// RMS, whether or not it is chosen.
    std::vector<double> stack_weights;
    double stack_rms_um = 0;
    /// The equal-weight mean's RMS (+∞ when no family may take part in it).
    double mean_rms_um = 0;
};

/// The families within one standard error of the best score among those
/// `inMean` allows (Hastie, Tibshirani & Friedman, §7.10; the standard error
/// of the best family's mean square over the parts, carried to its RMS; at
/// least 2 %), best first.
std::vector<std::size_t> nearBestFamilies(const std::vector<HeldOutPredictions>& families,
                                          const std::vector<bool>& inMean);

/// The stacked combination where its cross-validated RMS is 2 % below the
/// equal-weight mean's of the near-best families `inMean` allows, else that
/// mean: weights fitted on a few runs' folds vary with the folds' chance, and
/// a gain within it does not pay for the risk of a small weight on a family
/// that extrapolates badly. Then the no-harm guard: the choice where its
/// cross-validated RMS is below no compensation's (the measured errors' own
/// RMS), else the best family alone where it is, else no compensation.
CombinationChoice chooseCombination(const std::vector<HeldOutPredictions>& families,
                                    const std::vector<bool>& inMean);

}  // namespace driftlab::models
