#pragma once
// Which of a step's findings are causes: ranked by held-out gain with the
// confidence of each, and the rules that name the first and the second cause.
// The rules are about evidence, not about any one effect: one physical cause
// fitting every reading beats an effect on one sensor, and a cause is held to
// explaining most of the quantity it shows in.

#include <vector>

#include "core/diagnosis/Diagnosis.h"

namespace driftlab::diagnosis {

/// Best held-out gain first, each with its confidence (StretchJackknife);
/// `before` is what the step started from.
void rankFindings(std::vector<Finding>& findings,
                  const std::vector<models::ReadingResiduals>& before);

/// Marks significant an effect on the axis that the training runs do not
/// contradict but the held-out runs show (DiagnosisOptions::min_held_out_confidence).
void admitHeldOutEvidence(std::vector<Finding>& findings, const DiagnosisOptions& options);

/// The significant finding with the largest gain that is not a sensor effect
/// the physics explains on its sensor, or nullptr.
const Finding* bestSignificant(const std::vector<Finding>& findings,
                               const std::vector<models::ReadingResiduals>& before);

/// The second cause among `second`, the findings on top of `first`, or nullptr.
const Finding* secondCause(const std::vector<Finding>& second, const Finding& first,
                           const std::vector<models::ReadingResiduals>& before,
                           const DiagnosisOptions& options);

}  // namespace driftlab::diagnosis
