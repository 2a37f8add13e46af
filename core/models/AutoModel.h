#pragma once
// `fit --model auto`: chooses the model family, and with it the inputs, by
// cross-validation over the training runs only (each run left out in turn,
// and every run's first 70 % of time fitted to score the rest; with a single
// run, the latter alone), refits on all
// training runs and says what it chose and what the others scored. The
// families within one standard error of the best score are equally good on
// these runs (a few runs rank close families partly by chance): auto predicts
// with their mean, which varies less than any one of them (forecast
// combination; Bates & Granger 1969, Clemen 1989). No compensation is always
// a candidate: a family that does no better than it on these folds is never
// chosen, and when none does, auto says so and predicts no thermal error.
// The held-out test runs never take part in the choice.

#include <memory>
#include <vector>

#include "core/models/ModelValidation.h"
#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

class AutoModel final : public ThermalErrorModel {
public:
    QString name() const override { return QStringLiteral("auto"); }
    QString describe() const override;
    /// The families the last fit predicts with, best cross-validated score
    /// first, joined by " + " (their mean); "none" when no family beats no
    /// compensation; empty before a fit.
    QString chosen() const;
    /// The cross-validation of the choice (its held-out predictions on the
    /// folds it was chosen on: slightly optimistic, as every choice on the
    /// data it is judged by; the held-out runs' coverage checks it).
    const Validation& validation() const { return validation_; }

protected:
    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;

private:
    /// The summary of a mean of several families: each one's parameters,
    /// metrics and notes under its name.
    FitSummary combined(const std::vector<FitSummary>& fits) const;

    std::vector<std::unique_ptr<ThermalErrorModel>> chosen_;
    Validation validation_;
};

}  // namespace driftlab::models
