#pragma once
// One model fitted on training runs and scored on held-out runs: what
// `driftlab-cli fit` prints, what `batch` reports for each campaign and what
// the GUI can show, from the same code. Faults are ServiceErrors.

#include <QJsonObject>
#include <QStringList>
#include <functional>
#include <memory>
#include <optional>

#include "core/domain/Campaign.h"
#include "core/domain/ServiceError.h"
#include "core/models/ModelScore.h"
#include "core/models/ModelValidation.h"
#include "core/models/ThermalErrorModel.h"
#include "core/models/TrainingEnvelope.h"
#include "db/ModelFitStore.h"

namespace driftlab::db {

/// The runs' data for a model (`target`: a drift channel, or empty for the
/// positioning error); throws ServiceError naming what is missing.
std::vector<models::RunData> modelDataset(const Campaign& campaign, const QStringList& runs,
                                          const QString& target);
/// The model called `name`; throws ServiceError (BadRequest) naming the models there are.
std::unique_ptr<models::ThermalErrorModel> makeModelOrFail(const QString& name);

struct HeldOutFit {
    std::unique_ptr<models::ThermalErrorModel> model;
    QStringList trainRuns;
    QStringList testRuns;  ///< empty: no run held out, the score is a training score
    models::FitSummary fit;
    /// The model's cross-validation on its training runs: against no
    /// compensation, and its prediction interval.
    models::Validation validation;
    models::Score score;
    /// The share of the held-out readings inside the prediction interval.
    models::Coverage coverage;
    /// The holes of the training and scored runs' logs, bridged or left out.
    std::vector<models::DataGap> gaps;
    /// Where the held-out runs' temperatures leave the training runs' (the
    /// score there is an extrapolation's); empty without a held-out run.
    std::vector<models::RiseBeyondTraining> beyondTraining;
    std::vector<models::SpeedBeyondTraining> speedsBeyond;
    /// A held-out run goes beyond the training runs: its prediction extrapolates.
    bool extrapolates() const { return !beyondTraining.empty() || !speedsBeyond.empty(); }
    ModelFitRecord record;  ///< as the store keeps it

    bool heldOut() const { return !testRuns.isEmpty(); }
    /// The runs the score is on: the test runs, or the training runs when none is held out.
    QStringList scoredRuns() const { return heldOut() ? testRuns : trainRuns; }
    /// The held-out runs' thermal error is worse with the model than without.
    bool heldOutWorseThanNone() const { return heldOut() && score.reduction < 0; }
    /// `fit --json`: model, runs, parameters, score kind, score, test (with
    /// its coverage), validation, gaps, beyond_training, fit.
    QJsonObject json() const;
    /// What the text output says after the score: error-level lines where
    /// the model does harm, the interval's coverage, the gaps.
    QStringList trustLines() const;
};

struct HeldOutFitOptions {
    QString model;
    /// Without: the first modelled run that is not a test run.
    std::optional<QStringList> train;
    /// Without: every other modelled run (docs/models.md).
    std::optional<QStringList> test;
    QString target;  ///< a drift channel, or empty for the positioning error
    /// Told `what` is being done ("fitting heat-transfer") at 0 and at 1.
    std::function<void(const QString& what, double fraction)> progress;
    /// Asked between the steps and inside the fit; true stops it (ServiceError).
    std::function<bool()> cancelled;
};

/// Fits the model on the training runs and scores it on the test runs.
/// Throws ServiceError: BadRequest for an unknown model, Failed when the
/// data or the fit fail or when cancelled.
HeldOutFit fitHeldOut(const Campaign& campaign, const HeldOutFitOptions& options);

}  // namespace driftlab::db
