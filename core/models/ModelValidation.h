#pragma once
// How far a fitted model can be trusted on data it has not seen, from its
// training runs alone. The model is refitted on folds of the training runs
// (each run left out in turn, and every run's first 70 % of time fitted to
// score the rest) and predicted where each fold did not fit. That gives
//  - its cross-validated RMS beside that of no compensation on the same folds:
//    a model worse than none is not chosen by `auto`, nor pushed or exported
//    without an explicit override (no harm);
//  - a prediction interval: the 95th percentile of the held-out residuals'
//    magnitude, per target position for a positioning error (which grows
//    along the screw). This is split conformal prediction with folds (Vovk,
//    Gammerman & Shafer 2005; Barber et al. 2021, "jackknife+"): it assumes
//    nothing of the model's form, and the held-out runs' coverage checks it.
//    A run whose temperature rises or spindle speed go beyond the training
//    runs' (a higher speed, a warmer room: TrainingEnvelope.h) is an
//    extrapolation, which the
//    pooled folds mostly are not. Its interval is the wider of the pooled one
//    and that of the folds whose held-out part went beyond their own fit's
//    runs: calibrated on extrapolations, as the prediction is one.

#include <QString>
#include <QStringList>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

/// Runs to fit on, and runs (or late parts of runs) to predict.
struct ValidationFold {
    std::vector<RunData> fit_on;
    std::vector<RunData> held_out;
    /// Per held-out part: it goes beyond `fit_on` (beyondTraining), so its
    /// prediction is an extrapolation. Judged once, when the folds are made.
    std::vector<bool> held_out_beyond;
};

/// The folds of the training runs: with several, each left out in turn, and
/// every run's first 70 % of time fitted together to score each run's last
/// 30 %; with one, the latter alone.
std::vector<ValidationFold> validationFolds(const std::vector<RunData>& training);

/// "leaving each training run out in turn, and fitting every run's first 70 %
/// to score the rest", for notes.
QString describeValidationFolds(std::size_t trainingRuns);

/// The measured and predicted thermal error where the folds did not fit,
/// part by part (a held-out run, or a run's late part).
struct HeldOutPredictions {
    std::vector<double> measured_um, predicted_um, position_mm;
    std::vector<std::size_t> part_ends;  ///< one past each part's last reading
    /// Per part: its temperature rises go beyond those of the runs its fold
    /// fitted on (risesBeyondTraining).
    std::vector<bool> part_beyond;
    double rms_um() const;
    /// No compensation's RMS on the same readings: the measured error's own.
    double none_rms_um() const;
    /// The standard error of the RMS over the parts (0 with one part).
    double standard_error_um() const;
};

/// Makes a new, unfitted model: one per fold of a cross-validation.
using ModelMaker = std::function<std::unique_ptr<ThermalErrorModel>()>;

/// `family` refitted on each fold and predicted on its held-out parts;
/// throws ModelError with the family's reason when it cannot be, or when
/// `cancelled` says so.
HeldOutPredictions crossValidatedPredictions(const QString& family,
                                             const std::vector<ValidationFold>& folds,
                                             const std::function<bool()>& cancelled = {});
/// The same for a model no name makes (an adopted extension of heat-transfer).
HeldOutPredictions crossValidatedPredictions(const ModelMaker& make,
                                             const std::vector<ValidationFold>& folds,
                                             const std::function<bool()>& cancelled = {});

struct PredictionInterval {
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    double level = 0.95;
    double half_width_um = kNaN;  ///< over every reading
    /// Per target position (positioning error), ascending; interpolated
    /// linearly between targets and held beyond them.
    std::vector<double> position_mm, half_width_by_position_um;
    /// The same from the folds' extrapolations alone (NaN when fewer than
    /// kReadingsBeyond of their readings went beyond), on the same positions.
    double beyond_half_width_um = kNaN;
    std::vector<double> beyond_by_position_um;
    std::size_t beyond_readings = 0;
    QString method;  ///< how it was formed, for notes and the JSON
    bool known() const { return half_width_um == half_width_um; }
    bool knownBeyond() const { return beyond_half_width_um == beyond_half_width_um; }
    /// At a position of a run within the training runs' rises, or (`beyond`)
    /// of one that goes beyond them: then the wider of both intervals.
    double halfWidthAt(double position_mm, bool beyond = false) const;
};

/// ", ±4.5 µm on the held-out runs beyond the training runs" where `beyond`
/// and the interval there is known and wider; "" otherwise.
QString extrapolationWords(const PredictionInterval& interval, bool beyond);

/// Whether `run`'s temperature rises or spindle speed go beyond those of
/// `training` (TrainingEnvelope.h), so that its prediction is an extrapolation.
bool beyondTraining(const std::vector<RunData>& training, const RunData& run);

struct Validation {
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    double rms_um = kNaN;       ///< the model's cross-validated RMS
    double none_rms_um = kNaN;  ///< no compensation's, on the same readings
    std::size_t readings = 0;
    QString folds;  ///< describeValidationFolds
    PredictionInterval interval;
    bool known() const { return rms_um == rms_um; }
    /// Its prediction is worse than none where it was not fitted.
    bool worseThanNone() const { return known() && rms_um > none_rms_um; }
    /// "cross-validated RMS 0.41 µm (no compensation 3.2 µm)".
    QString describe() const;
    /// Empty, or why the model `what` names must not compensate a machine
    /// (no harm): "… does worse than no compensation where it was not fitted
    /// (…): it would make the machine worse".
    QString harmReason(const QString& what) const;
};

/// The validation the held-out predictions give: RMS, no compensation's and
/// the interval (per position when `positionDependent`).
Validation validationOf(const HeldOutPredictions& predictions, bool positionDependent,
                        std::size_t trainingRuns);

/// The share of the readings of `runs` whose residual lies within the
/// interval around the model's prediction (the interval beyond the training
/// runs on a run that goes beyond `training`).
struct Coverage {
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    double share = kNaN;
    double claimed = 0.95;
    std::size_t readings = 0;
    bool known() const { return share == share; }
    /// Covers more than ten points less than it claims.
    bool farBelowClaim() const { return known() && share < claimed - 0.10; }
};
Coverage coverageOf(const ThermalErrorModel& model, const PredictionInterval& interval,
                    const std::vector<RunData>& runs, const std::vector<RunData>& training);

/// `auto` chooses its combination on the very folds that score it, which
/// flatters it most where the choice matters most: beyond the training runs.
/// There its interval comes from `auto` itself refitted on each fold that
/// extrapolates, choice included (nested cross-validation; Varma & Simon
/// 2006). Sets `interval`'s beyond_* from those folds; throws ModelError.
void nestBeyondInterval(const std::vector<RunData>& training, PredictionInterval* interval,
                        const std::function<bool()>& cancelled = {});

/// A model fitted on its training runs and validated on their folds.
struct ValidatedFit {
    std::unique_ptr<ThermalErrorModel> model;
    FitSummary fit;
    Validation validation;
};

/// Fits `name` (a family, "none" or "auto") on `training` and validates it;
/// `auto` validates the combination it chose on its own folds. The fit's
/// success and message say whether it worked; a validation that cannot be
/// formed (a fold the family cannot fit) is left unknown with a note.
ValidatedFit fitValidated(const QString& name, const std::vector<RunData>& training,
                          const std::function<bool()>& cancelled = {});
/// The same for a model no name makes; `make` is called once per fold too.
ValidatedFit fitValidated(const ModelMaker& make, const std::vector<RunData>& training,
                          const std::function<bool()>& cancelled = {});

/// What a fit's user must know of its validation, as notes: the interval and
/// how it was formed, and a warning when it is worse than no compensation.
QStringList validationNotes(const Validation& validation);

}  // namespace driftlab::models
