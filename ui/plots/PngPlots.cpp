#include "ui/plots/PngPlots.h"

#include <qcustomplot.h>

#include <algorithm>

namespace driftlab::ui {
namespace {

void decorate(QCustomPlot& p, const QString& title, const QString& xLabel, const QString& yLabel) {
    p.plotLayout()->insertRow(0);
    auto* heading = new QCPTextElement(&p, title, QFont(QStringLiteral("sans"), 12, QFont::Bold));
    p.plotLayout()->addElement(0, 0, heading);
    p.xAxis->setLabel(xLabel);
    p.yAxis->setLabel(yLabel);
}

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
    const std::size_t nx = plot.x.size(), ny = plot.y.size();
    if (nx < 2 || ny < 2 || plot.z.size() != nx * ny) {
        *error = QStringLiteral("%1: map needs at least 2x2 points and z of size x*y").arg(path);
        return false;
    }
    QCustomPlot p;
    decorate(p, plot.title, plot.xLabel, plot.yLabel);
    auto* map = new QCPColorMap(p.xAxis, p.yAxis);
    map->data()->setSize(int(nx), int(ny));
    map->data()->setRange(QCPRange(plot.x.front(), plot.x.back()),
                          QCPRange(plot.y.front(), plot.y.back()));
    for (std::size_t iy = 0; iy < ny; ++iy)
        for (std::size_t ix = 0; ix < nx; ++ix)
            map->data()->setCell(int(ix), int(iy), plot.z[iy * nx + ix]);
    auto* scale = new QCPColorScale(&p);
    p.plotLayout()->addElement(1, 1, scale);
    scale->axis()->setLabel(plot.zLabel);
    map->setColorScale(scale);
    map->setGradient(QCPColorGradient::gpJet);
    map->rescaleDataRange(true);
    auto* margins = new QCPMarginGroup(&p);
    p.axisRect()->setMarginGroup(QCP::msBottom | QCP::msTop, margins);
    scale->setMarginGroup(QCP::msBottom | QCP::msTop, margins);
    p.rescaleAxes();
    return save(p, path, size, error);
}

bool saveCurvesPng(const CurvePlot& plot, const QString& path, QString* error, QSize size) {
    QCustomPlot p;
    decorate(p, plot.title, plot.xLabel, plot.yLabel);
    const int n = int(plot.curves.size());
    for (int i = 0; i < n; ++i) {
        const Curve& c = plot.curves[std::size_t(i)];
        if (c.x.size() != c.y.size()) {
            *error = QStringLiteral("%1: curve '%2' has %3 x and %4 y values")
                         .arg(path, c.name)
                         .arg(c.x.size())
                         .arg(c.y.size());
            return false;
        }
        QCPGraph* g = p.addGraph();
        g->setName(c.name);
        g->setData(QVector<double>(c.x.begin(), c.x.end()), QVector<double>(c.y.begin(), c.y.end()),
                   true);
        // Colours along a blue-to-red ramp: curves are usually successive times.
        const QColor colour = QColor::fromHsv(int(240 - 240.0 * i / std::max(1, n - 1)), 220, 200);
        g->setPen(QPen(colour, 2));
        if (c.markersOnly) {
            g->setLineStyle(QCPGraph::lsNone);
            g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, colour, 5));
        }
    }
    p.legend->setVisible(n > 1 && n <= 16);
    p.legend->setFont(QFont(QStringLiteral("sans"), 8));
    // Thermal errors grow with position and time: the top left is the free corner.
    p.axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    p.rescaleAxes();
    p.xAxis->scaleRange(1.02, p.xAxis->range().center());
    p.yAxis->scaleRange(1.08, p.yAxis->range().center());
    return save(p, path, size, error);
}

}  // namespace driftlab::ui
