#pragma once
// The work behind the Models page, run on a worker thread (BackgroundJob):
// fit one model and score it per held-out run, or compare every model on the
// cross-state matrix. Each opens its own store connection (a QSqlDatabase
// belongs to the thread that opened it) and leaves out the flagged samples as
// `driftlab-cli fit` does.

#include <QStringList>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "core/domain/Campaign.h"
#include "core/models/ModelScore.h"
#include "core/models/ModelValidation.h"
#include "core/models/TrainingEnvelope.h"
#include "db/FlaggedSampleMask.h"
#include "ui/shell/BackgroundJob.h"

namespace driftlab::ui {

/// The campaign as stored, with its flagged samples left out (and `note`
/// saying how many, `leftOut` what); nullopt with `error`.
std::optional<Campaign> loadCampaignForModels(const QString& storePath, qint64 campaignId,
                                              QString* note, QString* error,
                                              std::optional<db::MaskedSamples>* leftOut = nullptr);

/// What the model workbench offers for a campaign: the targets ("" = the
/// positioning error, then the drift channels) and the runs of each.
struct ModelledRunLists {
    QString error;
    QStringList targets;
    std::map<QString, QStringList> runs;  ///< by target
};

ModelledRunLists listModelledRuns(const QString& storePath, qint64 campaignId);

struct FitRequest {
    QString store_path;
    qint64 campaign_id = 0;
    QString model;
    QString target_channel;  ///< empty: the positioning error
    QStringList train_runs, test_runs;
};

/// One test run: its measured thermal error and the fitted model's prediction
/// at the observation points, and its own score.
struct RunPrediction {
    QString run_id;
    std::vector<models::ErrorObservation> observations;
    std::vector<double> predicted_um;
    /// The half-width of the prediction interval (95 %) at each point.
    std::vector<double> interval_um;
    models::Score score;
};

struct FitOutcome {
    QString error;  ///< empty on success (and when cancelled)
    bool cancelled = false;
    QString note;                             ///< e.g. flagged samples left out
    std::optional<db::MaskedSamples> masked;  ///< the flagged samples left out, stored with the fit
    models::FitSummary fit;
    models::Score pooled;  ///< over every test run; with none, on the training runs
    bool held_out = false;
    std::vector<RunPrediction> runs;  ///< per test run
    /// Where the test runs' temperatures leave the training runs'.
    std::vector<models::RiseBeyondTraining> beyond_training;
    std::vector<models::SpeedBeyondTraining> speeds_beyond;
    /// The fit's cross-validation against no compensation and its interval,
    /// and the share of the held-out readings inside the interval.
    models::Validation validation;
    models::Coverage coverage;
    /// The holes of the training and test runs' logs, bridged or left out.
    std::vector<models::DataGap> gaps;
    std::optional<qint64> fit_id;  ///< the stored record
};

/// Fits and validates (models::fitValidated), scores per test run and stores
/// the fit (db::storeModelFit) unless cancelled. Cancel stops the fit between
/// solver iterations.
FitOutcome runFit(const FitRequest& request, JobControl& control);

struct CompareOutcome {
    QString error;
    bool cancelled = false;
    QString note;
    QStringList runs;
    /// Per model, in models::modelNames() order: rms_um[i][j].
    std::vector<std::pair<QString, models::CrossStateMatrix>> matrices;
};

/// The cross-state matrix of every model, as `driftlab-cli compare`
/// (heat-transfer is left out for a drift target).
CompareOutcome runCompare(const QString& storePath, qint64 campaignId, const QString& target,
                          JobControl& control);

}  // namespace driftlab::ui
