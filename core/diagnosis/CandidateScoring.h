#pragma once
// One candidate effect tried on top of what a diagnosis step starts from:
// refitted on the training runs, scored on the held-out runs on the quantity
// the effect shows in, with the evidence in a test engineer's words.

#include <functional>
#include <optional>

#include "core/diagnosis/Diagnosis.h"

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
};

/// `candidate` fitted on top of `base` from `ownStart` (its own parameters'
/// starting values; empty: their defaults); nullopt when the data cannot carry
/// it or the fit was cancelled.
std::optional<Finding> scoreCandidate(const StepBase& base, const CandidateEffect& candidate,
                                      const std::vector<double>& ownStart, int step,
                                      const StepData& data);

/// What the fitted effect means on this machine, and what it does to the
/// held-out residuals.
QString evidenceFor(const Finding& finding, const QStringList& testRuns);

}  // namespace driftlab::diagnosis
