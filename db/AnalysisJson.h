#pragma once
// The JSON of `info --json` and `iso230-2 --json`: what those commands print
// and what `batch` reports for each campaign, built in one place.

#include <QJsonObject>

#include "core/domain/Campaign.h"
#include "core/iso/Iso230_2.h"

namespace driftlab::db {

/// `info --json`: name, machine, axis, runs (id, kind, counts, duration), channels.
QJsonObject campaignInfoJson(const Campaign& campaign);

/// `iso230-2 --json` without its source: edition, coverage factor, the axis
/// values (B, R, E, M, A, …) in µm, cycles, per-target detail, what was skipped.
QJsonObject iso230EvaluationJson(const iso::Evaluation& evaluation);

}  // namespace driftlab::db
