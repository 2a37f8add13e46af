#pragma once
// `fit --model auto`: chooses the model family, and with it the inputs, by
// cross-validation over the training runs only (each run left out in turn,
// and every run's first 70 % of time fitted to score the rest; with a single
// run, the latter alone), refits on all
// training runs and says what it chose and what the others scored. The
// families within one standard error of the best score are equally good on
// these runs (a few runs rank close families partly by chance): auto predicts
// with their mean, which varies less than any one of them (forecast
// combination; Bates & Granger 1969, Clemen 1989).
// The held-out test runs never take part in the choice.

#include <memory>
#include <vector>

#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

class AutoModel final : public ThermalErrorModel {
public:
    QString name() const override { return QStringLiteral("auto"); }
    QString describe() const override;
    /// The families the last fit predicts with, best cross-validated score
    /// first, joined by " + " (their mean); empty before a fit.
    QString chosen() const;

protected:
    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;

private:
    struct CrossValidatedScore {
        double rms_um;
        double standard_error_um;  ///< over the folds; 0 with a single fold
    };
    /// Runs to fit on, and runs (or parts of runs) to score on.
    struct Fold {
        std::vector<RunData> fit_on;
        std::vector<RunData> held_out;
    };
    /// The folds every family is scored on, built once per fit.
    static std::vector<Fold> foldsOf(const std::vector<RunData>& training);
    /// RMS of the family's predictions on data it was not fitted on; throws
    /// ModelError with the family's reason when it cannot be fitted.
    CrossValidatedScore crossValidatedRms(const QString& family,
                                          const std::vector<Fold>& folds) const;
    /// The summary of a mean of several families: each one's parameters,
    /// metrics and notes under its name.
    FitSummary combined(const std::vector<FitSummary>& fits) const;

    std::vector<std::unique_ptr<ThermalErrorModel>> chosen_;
};

}  // namespace driftlab::models
