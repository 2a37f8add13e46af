#pragma once
// How far a fit can be trusted, as JSON: its cross-validation against no
// compensation and its prediction interval, the interval's coverage on
// held-out runs, and the holes of the log it bridged or left out. The same
// objects in `fit --json`, `diagnose --json`, `batch` and the stored fit.

#include <QJsonArray>
#include <QJsonObject>
#include <vector>

#include "core/models/DataGaps.h"
#include "core/models/ModelValidation.h"

namespace driftlab::db {

/// {"cv_rms_um", "none_cv_rms_um", "worse_than_none", "readings", "folds",
///  "interval": {"level", "half_width_um", "by_position": [{"position_mm",
///  "half_width_um"}], "beyond_training": {"half_width_um", "by_position",
///  "readings"} ({} when unknown), "method"}}; {} when unknown.
QJsonObject validationJson(const models::Validation& validation);

/// {"share", "claimed", "readings", "far_below_claim"}; {} when unknown.
QJsonObject coverageJson(const models::Coverage& coverage);

/// One object per hole: {"run", "channel", "from_s", "to_s", "treatment":
/// "bridged"|"left_out", "bridge_error", "tolerance", "unit",
/// "observations_left_out"}.
QJsonArray gapsJson(const std::vector<models::DataGap>& gaps);

}  // namespace driftlab::db
