#pragma once
// The trend of a machine axis's ISO 230-2 figures over its campaigns
// (docs/history.md): A, E, R, B and M against the campaign date, for the
// CLI's PNG, the report and the GUI.

#include "core/history/MachineHistory.h"
#include "ui/plots/PngPlots.h"

namespace driftlab::ui {

/// One curve per figure, a point per campaign where the figure is determined.
CurvePlot historyTrendPlot(const history::MachineHistory& history);

}  // namespace driftlab::ui
