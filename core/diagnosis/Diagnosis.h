#pragma once
// What the simulation gets wrong, its cause, the extended model and its gain
// (docs/diagnosis.md): fit the base heat-transfer model on training runs,
// refit every candidate effect, score all on held-out runs on the quantity
// each effect shows in, name the cause when its gain is real and significant
// and it explains most of what the base model leaves; then test the rest again
// on top of the adopted extension, so a second effect is found too.

#include <QStringList>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "core/diagnosis/CandidateEffects.h"
#include "core/diagnosis/ResidualStructure.h"
#include "core/diagnosis/StretchJackknife.h"
#include "core/domain/Campaign.h"
#include "core/models/HeatTransferModel.h"

namespace driftlab::diagnosis {

struct DiagnosisOptions {
    QStringList train_runs, test_runs;  ///< both empty: split automatically
    /// An extension is significant when it lowers BIC on the training runs,
    /// of the quantity it shows in, by more than this (≈ "very strong"
    /// evidence in Kass & Raftery's scale) …
    double min_bic_drop = 10;
    /// … and removes at least this share of that quantity's held-out residual.
    double min_test_gain = 0.05;
    /// A significant extension is named when it leaves the held-out residual
    /// within this many times the reading noise (see leavesOnlyNoise) …
    double max_residual_over_noise = 2;
    /// … or removes at least this share of it (then what remains is described).
    double min_explained = 0.6;
    /// A second cause is named on top of the first when it removes at least
    /// this share of what the first one leaves (a sensor effect on a sensor
    /// the first cause did not show in: min_explained of that sensor's).
    double min_second_gain = 0.2;
    /// On a base model that fits to the noise (kNoiseLevelTolerance) a cause
    /// is named only with at least this confidence: the held-out stretches
    /// then show that part of what the noise estimate took for noise is its
    /// effect (a refraction of 0.7 µm against 0.5 µm of reading noise).
    double min_confidence_at_noise = 0.9;
    /// An effect on the axis that the training runs do not contradict (ΔBIC
    /// above 0, below min_bic_drop) is significant all the same when it
    /// removes min_explained of the held-out residual with at least this
    /// confidence: held-out runs at other speeds can show a speed law that
    /// training runs at two close speeds cannot (nut heat, n = 0.75).
    double min_held_out_confidence = 0.99;
    std::function<bool(double fraction)> progress;  ///< false cancels
};

/// The held-out gain of an extension on the quantity its effect shows in:
/// the positioning error for effects on the axis or the interferometer, the
/// sensor's own temperature for sensor effects.
struct Gain {
    QString quantity;  ///< "positioning" or "temperature:<channel>"
    QString unit;      ///< "µm" or "K"
    double test_rms_before = 0, test_rms_after = 0;
    double reduction = 0;  ///< 1 − after/before
    /// The quantity's sums of squares per stretch of the held-out runs.
    StretchSquares stretches;
};

struct Finding {
    QString cause;
    /// 1: tested on the base model; 2: on top of the cause adopted in step 1.
    int step = 1;
    CandidateEffect effect;
    /// The effect's own fitted parameters, in its order.
    std::vector<std::pair<QString, models::Parameter>> parameters;
    /// The probability that the held-out gain is real and larger than every
    /// other candidate's of the same step (see rank in Diagnosis.cpp); for a
    /// cause named, times the share of the structure the causes explain.
    double confidence = 0;
    bool significant = false;
    /// It buys its gain by making the other kind of reading worse (see
    /// scoreCandidate): not a cause, and no competitor of one.
    bool fit_compromise = false;
    double bic_drop = 0;  ///< on the training runs, of the gain's quantity
    QString evidence;
    Gain gain;
    /// Both quantities on the held-out runs before (the step's base) and after.
    ResidualSummary test_before, test_after;
    /// What the extension leaves on the training and the held-out runs.
    std::vector<models::ReadingResiduals> train_residuals, test_residuals;
    models::FitSummary fit;
    std::shared_ptr<const models::HeatTransferModel> model;  ///< the fitted extension
};

struct DiagnosisResult {
    QString error;  ///< empty on success
    bool ok() const { return error.isEmpty(); }
    QStringList train_runs, test_runs;
    models::FitSummary base_fit;
    ResidualSummary base_test;
    /// Step 1 sorted by held-out gain, best first, then step 2 likewise.
    std::vector<Finding> findings;
    QStringList causes;        ///< the adopted causes in the order found
    QString verdict;           ///< the first cause, "none" or "unexplained"
    QString verdict_evidence;  ///< for none/unexplained: what the residual is
    /// With a cause: what the adopted extension leaves when it is more than
    /// noise, where it sits and what it follows.
    QString remaining;
    /// With a cause: the share of the positioning structure above the reading
    /// noise that the causes explain (structureExplained); it scales their
    /// confidences.
    double structure_explained = 0;
    /// The base residuals on the test runs (for the residual map).
    std::vector<models::ReadingResiduals> base_residuals;
    /// The holes of the training and test runs' logs, bridged or left out.
    std::vector<models::DataGap> gaps;
};

/// The finding of an adopted cause (the step it was adopted in), or nullptr.
const Finding* adoptedFinding(const DiagnosisResult& result, const QString& cause);

/// The finding whose model is the adopted extension with every cause found
/// (the last cause's, fitted on top of the ones before), or nullptr (verdict
/// none/unexplained).
const Finding* verdictFinding(const DiagnosisResult& result);

/// What that extension leaves on held-out run `k`, or nullptr without a cause.
const models::ReadingResiduals* adoptedResiduals(const DiagnosisResult& result, std::size_t k);

/// "dh_800rpm = 3.1 ± 0.2 W/(m²·K), m = 1.4 ± 0.1".
QString parametersText(const Finding& finding);

/// Runs split automatically: the last 40 % (at least one) of the feed-axis
/// runs are the test runs, the rest train; no run is in both.
void splitRuns(const Campaign& campaign, QStringList* train, QStringList* test);

DiagnosisResult diagnose(const Campaign& campaign, const DiagnosisOptions& options = {});

}  // namespace driftlab::diagnosis
