#pragma once
// ISO 230-2 asks for irregularly spaced targets: a ball screw's periodic
// error repeats every lead, and targets that all fall at the same phase of
// the lead sample it at one value, so it shows up in the table as a constant
// offset instead of being seen for what it is (docs/compensation.md).

#include <QString>
#include <vector>

namespace driftlab::compensation {

/// Targets this close to a common phase of the lead count as on it (the
/// targets of a programme are nominal positions, typed to 1 µm).
constexpr double kLeadPhaseToleranceMm = 0.001;

/// A warning when every measured target (at least three) lies at the same
/// phase of the screw lead, i.e. every distance between targets is a whole
/// number of leads; empty otherwise and when the lead is unknown (≤ 0).
QString leadAliasingWarning(const std::vector<double>& targets_mm, double lead_mm);

}  // namespace driftlab::compensation
