#pragma once
// Draws a figure of the report into a painter: a PDF page (vectors) or an
// image (the HTML report's PNG). The same QCustomPlot drawing as the GUI's
// pages (Iso230_2Plot, PlotDrawing). Widgets: on the GUI thread only.

#include <QImage>
#include <QSize>

#include "ui/report/ReportDocument.h"

class QCPPainter;

namespace driftlab::ui::report {

/// Draws `plot` into `painter` at (0, 0), width × height.
void paintPlot(const Plot& plot, QCPPainter& painter, QSize size);
/// `plot` as an image of `size`, white background.
QImage plotImage(const Plot& plot, QSize size);

}  // namespace driftlab::ui::report
