#pragma once
// The ISO 230-3 figures of a drift run against the specification's
// tolerances (`iso230_3_um`), by the same decision rule as ISO 230-2's values
// (docs/acceptance.md).

#include <vector>

#include "core/iso/AcceptanceSpecification.h"
#include "core/iso/ConformanceDecision.h"
#include "core/iso/Iso230_3.h"

namespace driftlab::iso {

/// The figures a tolerance can be set for (iso230_3ParameterKeys()).
struct DriftFigures {
    double max_drift_um = 0;    ///< the largest |drift| of any target, direction or probe
    double drift_range_um = 0;  ///< the largest range (max − min) of any of them
};
DriftFigures driftFigures(const AxisDriftEvaluation& evaluation);
DriftFigures driftFigures(const ProbeDriftEvaluation& evaluation);

/// The expanded uncertainty of a drift figure. A drift compares readings of
/// one target or probe over time, as R and B do: an error proportional to
/// length is common to both and cancels; the device's length-independent part
/// and the environmental variation error (`eve_um` of the specification) stay.
double driftExpandedUncertainty_um(const SetupUncertainty& setup);

/// One decision per figure the axis has a tolerance for; empty without one.
std::vector<Decision> driftDecisions(const AcceptanceSpecification& specification,
                                     const QString& axis, const DriftFigures& figures);

}  // namespace driftlab::iso
