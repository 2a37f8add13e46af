#pragma once
// `fit --model auto`: chooses the model family, and with it the inputs, by
// cross-validation over the training runs only (leave one run out; with a
// single run, fit on its first 70 % and score on the rest), takes the simplest
// family within one standard error of the best (a few runs rank close families
// partly by chance), refits it on all training runs and says what it chose and
// what the others scored.
// The held-out test runs never take part in the choice.

#include <memory>

#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

class AutoModel final : public ThermalErrorModel {
public:
    QString name() const override { return QStringLiteral("auto"); }
    QString describe() const override;
    /// The family chosen by the last fit; empty before.
    QString chosen() const { return chosen_ ? chosen_->name() : QString(); }

protected:
    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;

private:
    struct CrossValidatedScore {
        double rms_um;
        double standard_error_um;  ///< over the folds; 0 with a single fold
    };
    /// RMS of the family's predictions on data it was not fitted on; throws
    /// ModelError with the family's reason when it cannot be fitted.
    CrossValidatedScore crossValidatedRms(const QString& family,
                                          const std::vector<RunData>& training) const;

    std::unique_ptr<ThermalErrorModel> chosen_;
};

}  // namespace driftlab::models
