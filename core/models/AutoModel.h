#pragma once
// `fit --model auto`: combines the model families, and with them the inputs,
// by cross-validation over the training runs only (each run left out in turn,
// and every run's first 70 % of time fitted to score the rest; with a single
// run, the latter alone). Every family's held-out predictions on those folds
// are stacked (StackedCombination.h): weights of at least zero summing to one
// that minimise the squared error of their weighted sum (Wolpert 1992;
// Breiman 1996). Where the stack's cross-validated RMS is not 2 % below that
// of the equal-weight mean of the families within one standard error of the
// best (Hastie, Tibshirani & Friedman, §7.10; forecast combination, Bates &
// Granger 1969, Clemen 1989), auto predicts with that mean: weights fitted on
// a few runs' folds follow the folds' chance, and an equal-weight mean is
// hard to beat unless the weights gain clearly (Smith & Wallis 2009). The
// families chosen are refitted on all training runs. No harm: where the
// choice's cross-validated RMS is not below no compensation's, auto falls
// back to the best family alone if that is, else predicts no thermal error
// and says so. The held-out test runs never take part in the choice.

#include <memory>
#include <vector>

#include "core/models/ModelValidation.h"
#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

class AutoModel final : public ThermalErrorModel {
public:
    QString name() const override { return QStringLiteral("auto"); }
    QString describe() const override;
    /// The families the last fit predicts with, heaviest weight first (of a
    /// mean, best cross-validated score first), joined by " + "; "none" when
    /// nothing beats no compensation; empty before a fit.
    QString chosen() const;
    /// Their weights, in the same order, summing to one.
    const std::vector<double>& weights() const { return m_weights; }
    /// The cross-validation of the choice (its held-out predictions on the
    /// folds it was chosen on: slightly optimistic, as every choice on the
    /// data it is judged by; the held-out runs' coverage checks it).
    const Validation& validation() const { return m_validation; }

protected:
    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;

private:
    /// The summary of a combination of several families: each one's
    /// parameters, metrics and notes under its name.
    FitSummary combined(const std::vector<FitSummary>& fits) const;

    std::vector<std::unique_ptr<ThermalErrorModel>> m_chosen;
    std::vector<double> m_weights;
    Validation m_validation;
};

}  // namespace driftlab::models
