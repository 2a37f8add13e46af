#include "ui/plots/PlotDrawing.h"

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

}  // namespace

QString mapProblem(const MapPlot& plot) {
    const std::size_t nx = plot.x.size(), ny = plot.y.size();
    if (nx < 2 || ny < 2 || plot.z.size() != nx * ny)
        return QStringLiteral("map needs at least 2x2 points and z of size x*y");
    return {};
}

QString curvesProblem(const CurvePlot& plot) {
    for (const Curve& c : plot.curves)
        if (c.x.size() != c.y.size())
            return QStringLiteral("curve '%1' has %2 x and %3 y values")
                .arg(c.name)
                .arg(c.x.size())
                .arg(c.y.size());
    return {};
}

void drawMap(QCustomPlot& p, const MapPlot& plot) {
    const std::size_t nx = plot.x.size(), ny = plot.y.size();
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
}

void drawCurves(QCustomPlot& p, const CurvePlot& plot) {
    decorate(p, plot.title, plot.xLabel, plot.yLabel);
    const int n = int(plot.curves.size());
    for (int i = 0; i < n; ++i) {
        const Curve& c = plot.curves[std::size_t(i)];
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
    for (int i = 0; i < n; ++i) {
        const int upper = plot.curves[std::size_t(i)].bandOf;
        if (upper < 0 || upper >= n || upper == i) continue;
        QCPGraph* edge = p.graph(upper);
        QColor shade = edge->pen().color();
        shade.setAlpha(40);
        edge->setBrush(shade);
        edge->setChannelFillGraph(p.graph(i));
        p.graph(i)->setPen(edge->pen());
        p.graph(i)->removeFromLegend();
    }
    if (plot.xIsDate) {
        auto dates = QSharedPointer<QCPAxisTickerDateTime>::create();
        dates->setDateTimeFormat(QStringLiteral("yyyy-MM-dd"));
        dates->setDateTimeSpec(Qt::UTC);
        p.xAxis->setTicker(dates);
        // A history has a few campaigns far apart: each one is a point.
        for (int i = 0; i < n; ++i)
            p.graph(i)->setScatterStyle(
                QCPScatterStyle(QCPScatterStyle::ssCircle, p.graph(i)->pen().color(), 7));
    }
    p.legend->setVisible(n > 1 && n <= 16);
    p.legend->setFont(QFont(QStringLiteral("sans"), 8));
    // Thermal errors grow with position and time: the top left is the free corner.
    p.axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    p.rescaleAxes();
    p.xAxis->scaleRange(1.02, p.xAxis->range().center());
    p.yAxis->scaleRange(1.08, p.yAxis->range().center());
}

}  // namespace driftlab::ui
