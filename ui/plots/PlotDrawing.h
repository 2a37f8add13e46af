#pragma once
// Draws the plot descriptions of PngPlots.h into a QCustomPlot: the same
// picture in a PNG (CLI, reports) and in a widget (the GUI's pages). Only ui
// sources include this (QCustomPlot is a private dependency of ui).

#include <QString>

#include "ui/plots/PngPlots.h"

class QCustomPlot;

namespace driftlab::ui {

/// Why the map cannot be drawn (fewer than 2×2 points, z not of size x·y), or empty.
QString mapProblem(const MapPlot& plot);
/// Why the curves cannot be drawn (a curve with unequal x and y), or empty.
QString curvesProblem(const CurvePlot& plot);

/// Draws into an empty `p` (title row, axes, colour scale / legend).
/// The plot must have no problem.
void drawMap(QCustomPlot& p, const MapPlot& plot);
void drawCurves(QCustomPlot& p, const CurvePlot& plot);

}  // namespace driftlab::ui
