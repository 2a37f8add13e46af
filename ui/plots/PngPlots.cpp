#include "ui/plots/PngPlots.h"

#include <qcustomplot.h>

#include "ui/plots/PlotDrawing.h"

namespace driftlab::ui {
namespace {

bool save(QCustomPlot& p, const QString& path, QSize size, QString* error) {
    p.resize(size);
    p.replot();
    if (!p.savePng(path, size.width(), size.height())) {
        *error = QStringLiteral("%1: cannot write PNG").arg(path);
        return false;
    }
    return true;
}

}  // namespace

bool saveMapPng(const MapPlot& plot, const QString& path, QString* error, QSize size) {
    if (const QString problem = mapProblem(plot); !problem.isEmpty()) {
        *error = QStringLiteral("%1: %2").arg(path, problem);
        return false;
    }
    QCustomPlot p;
    drawMap(p, plot);
    return save(p, path, size, error);
}

bool saveCurvesPng(const CurvePlot& plot, const QString& path, QString* error, QSize size) {
    if (const QString problem = curvesProblem(plot); !problem.isEmpty()) {
        *error = QStringLiteral("%1: %2").arg(path, problem);
        return false;
    }
    QCustomPlot p;
    drawCurves(p, plot);
    return save(p, path, size, error);
}

}  // namespace driftlab::ui
