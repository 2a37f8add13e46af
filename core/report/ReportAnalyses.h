#pragma once
// The model-based sections of the acceptance report: the cross-state matrix
// of every model (as `driftlab-cli compare`), the diagnosis (as `diagnose`)
// and the compensation table with the error it leaves (as `compensate`).

#include "core/report/AcceptanceReportData.h"

namespace driftlab::report {

/// `progress` gets the fraction of this part; false cancels.
ModelSection compareModels(const Campaign& campaign, const std::function<bool(double)>& progress);
DiagnosisSection diagnoseCampaign(const Campaign& campaign,
                                  const std::function<bool(double)>& progress);
/// The table from the ISO 230-2 evaluation of `positioning`, default layout
/// and limits (those of `compensate --format csv`).
CompensationSection compensate(const PositioningSection& positioning);

}  // namespace driftlab::report
