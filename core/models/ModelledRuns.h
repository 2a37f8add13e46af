#pragma once
// Which runs of a campaign a model can be fitted to and scored on, and which
// drift channels it can take as target: the same answer for `driftlab-cli fit`,
// `compare` and the GUI's model workbench.

#include <QStringList>

#include "core/domain/Campaign.h"

namespace driftlab::models {

/// Runs whose thermal error a model can be fitted to: feed-axis runs with
/// positioning data that include the cold reference cycle 0 (empty `targetChannel`), or the
/// spindle/ETVE runs that log the drift channel `targetChannel`. In campaign order.
QStringList modelledRuns(const Campaign& campaign, const QString& targetChannel = {});

/// Why no run is modelled, for an error that names what is missing: feed-axis
/// runs measured without a cold reference, or no run logging the target.
QString whyNoModelledRun(const Campaign& campaign, const QString& targetChannel = {});

/// The displacement channels that some spindle/ETVE run logs: the drift
/// targets a model can take (`--target`). In declaration order.
QStringList driftTargets(const Campaign& campaign);

}  // namespace driftlab::models
