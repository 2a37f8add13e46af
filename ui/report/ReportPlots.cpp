#include "ui/report/ReportPlots.h"

#include <qcustomplot.h>

#include "ui/plots/PlotDrawing.h"
#include "ui/widgets/Iso230_2Plot.h"

namespace driftlab::ui::report {

void paintPlot(const Plot& plot, QCPPainter& painter, QSize size) {
    if (plot.iso230_2) {
        Iso230_2Plot widget;
        widget.resize(size);
        widget.show(*plot.iso230_2, plot.accuracy_tolerance_um);
        widget.render(&painter, size.width(), size.height());
        return;
    }
    QCustomPlot p;
    p.resize(size);
    // Text as text, not cached pixmaps: a PDF keeps it sharp and searchable.
    p.setPlottingHint(QCP::phCacheLabels, false);
    if (plot.map && mapProblem(*plot.map).isEmpty())
        drawMap(p, *plot.map);
    else if (plot.curves && curvesProblem(*plot.curves).isEmpty())
        drawCurves(p, *plot.curves);
    p.replot();
    p.toPainter(&painter, size.width(), size.height());
}

QImage plotImage(const Plot& plot, QSize size) {
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::white);
    QCPPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    paintPlot(plot, painter, size);
    painter.end();
    return image;
}

}  // namespace driftlab::ui::report
