#pragma once
// One candidate effect tried on top of what a diagnosis step starts from:
// refitted on the training runs, scored on the held-out runs on the quantity
// the effect shows in, with the evidence in a test engineer's words.

#include <functional>
#include <optional>

#include "core/diagnosis/Diagnosis.h"
#include "core/diagnosis/OutputEffectFit.h"

namespace driftlab::diagnosis {

/// The model a diagnosis step extends (the base model, or the base with the
/// causes adopted so far) and what it leaves on the training and test runs.
struct StepBase {
    std::vector<CandidateEffect> effects;
    std::shared_ptr<const models::HeatTransferModel> model;
    std::vector<models::ReadingResiduals> train, test;
    ResidualSummary test_summary;
};

/// The first step: the fitted base model and what it leaves.
StepBase baseStep(std::shared_ptr<const models::HeatTransferModel> base,
                  const std::vector<models::RunData>& train,
                  const std::vector<models::RunData>& test);

/// The step that starts from an adopted finding: its fitted extension (the
/// causes `effects`, in order) and the residuals it was scored by.
StepBase adoptedStepBase(std::vector<CandidateEffect> effects, const Finding& adopted);

/// The runs a step fits on and scores on, and how it is judged.
struct StepData {
    const std::vector<models::RunData>& train;
    const std::vector<models::RunData>& test;
    const QStringList& test_ids;
    const DiagnosisOptions& options;
    std::function<bool()> cancelled;
    /// The step's simulation, which effects on the readings are fitted on.
    const StepSimulation* simulation = nullptr;
    /// The step's model refitted on the screening grid, which effects on the
    /// heat flow are first judged against (screeningStep).
    const StepBase* screening = nullptr;
};

/// The grid an effect that changes the heat flow is first fitted on, from
/// two starts (the step's fitted values, and the physical priors of the base
/// parameters); the better of the two is refined on the model's own grid.
/// Four times fewer cells and steps than the identification grid, whose
/// identified values it matches to about 1 % on the rig.
inline constexpr int kScreeningCells = 40;
inline constexpr double kScreeningStep_s = 5;
/// A screened candidate is refined when its held-out gain there exceeds this
/// share of DiagnosisOptions::min_test_gain: one that cannot be named is not.
inline constexpr double kRefineAbove = 0.5;
/// Iterations of the refinement: from the screening's values an extension
/// the data determine converges within a few; one that runs to a bound (a
/// speed exponent of 3 bending the heat balance) is judged where it stands.
inline constexpr int kRefineIterations = 15;

/// `options` on the screening grid.
models::HeatTransferOptions screeningOptions(const models::HeatTransferOptions& options);

/// The step's model refitted on the screening grid from its values, and what
/// it leaves on the training and test runs; nullopt when that fit fails.
std::optional<StepBase> screeningStep(const StepBase& base,
                                      const std::vector<models::RunData>& train,
                                      const std::vector<models::RunData>& test,
                                      const std::function<bool()>& cancelled);

/// `candidate` fitted on top of `base` from `ownStart` (its own parameters'
/// starting values; empty: their defaults), judged on the held-out runs;
/// nullopt when the data cannot carry it or the fit was cancelled. An effect
/// on the readings is fitted on the step's simulation (StepSimulation); one
/// that changes the heat flow on the screening grid from two starts, then on
/// the model's grid from the better: a base fit that bent its parameters to
/// follow part of the effect (bearing heat absorbing motor heat) does not
/// keep the candidate in its valley.
std::optional<Finding> scoreCandidate(const StepBase& base, const CandidateEffect& candidate,
                                      const std::vector<double>& ownStart, int step,
                                      const StepData& data);

/// What the fitted effect means on this machine, and what it does to the
/// held-out residuals.
QString evidenceFor(const Finding& finding, const QStringList& testRuns);

}  // namespace driftlab::diagnosis
