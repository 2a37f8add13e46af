#include "ui/widgets/LiveOffsetPlot.h"

#include <qcustomplot.h>

#include <QVBoxLayout>
#include <cmath>

namespace driftlab::ui {
namespace {

const QColor kSent(0x1f, 0x5f, 0xbf);
const QColor kModel(0x30, 0x30, 0x30);
const QColor kBand(0x60, 0x80, 0xb0, 70);
const QColor kCut(0xe0, 0x80, 0x00, 45);

QCPGraph* addCurve(QCustomPlot& plot, const QString& name, const QVector<double>& x,
                   const QVector<double>& y, const QPen& pen) {
    QCPGraph* graph = plot.addGraph();
    graph->setName(name);
    graph->setData(x, y, true);
    graph->setPen(pen);
    return graph;
}

}  // namespace

LiveOffsetPlot::LiveOffsetPlot(QWidget* parent) : QWidget(parent), m_plot(new QCustomPlot(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    m_plot->xAxis->setLabel(tr("Time in the run (min)"));
    m_plot->yAxis->setLabel(tr("Offset at the working position (µm)"));
    m_plot->legend->setVisible(false);  // an empty key until there is something to name
    m_plot->legend->setFont(QFont(font().family(), 8));
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignHCenter);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    setMinimumSize(320, 220);
}

void LiveOffsetPlot::clear() {
    m_plot->clearGraphs();
    m_plot->clearItems();
    m_cuts.clear();
    m_plot->legend->setVisible(false);
    m_plot->replot();
}

int LiveOffsetPlot::graphCount() const {
    return m_plot->graphCount();
}

void LiveOffsetPlot::addCut(double from_s, double to_s) {
    // Shaded over the plot's full height, behind the curves.
    auto* rect = new QCPItemRect(m_plot);
    rect->setPen(Qt::NoPen);
    rect->setBrush(kCut);
    rect->setLayer(QStringLiteral("background"));
    for (QCPItemPosition* corner : {rect->topLeft, rect->bottomRight}) {
        corner->setTypeX(QCPItemPosition::ptPlotCoords);
        corner->setTypeY(QCPItemPosition::ptAxisRectRatio);
    }
    rect->topLeft->setCoords(from_s / 60, 0);
    rect->bottomRight->setCoords(to_s / 60, 1);
    m_cuts.push_back(rect);
    m_plot->replot();
}

void LiveOffsetPlot::show(const std::vector<compensation::LiveUpdate>& updates,
                          double uncertainty_um) {
    m_plot->clearGraphs();
    if (!m_cuts.empty()) {
        // One legend entry for all cuts: an empty graph with the cuts' fill.
        QCPGraph* key = m_plot->addGraph();
        key->setName(tr("cutting: updates held"));
        key->setPen(Qt::NoPen);
        key->setBrush(kCut);
    }
    QVector<double> t, sent, model, low, high;
    for (const compensation::LiveUpdate& u : updates) {
        t << u.time_s / 60;
        sent << u.offset_um;
        model << u.target_offset_um;
        low << u.target_offset_um - uncertainty_um;
        high << u.target_offset_um + uncertainty_um;
    }
    if (std::isfinite(uncertainty_um)) {
        // The band's key is its upper edge, which carries the fill.
        QCPGraph* lower = addCurve(*m_plot, QString(), t, low, QPen(kBand));
        m_plot->legend->removeItem(m_plot->legend->itemCount() - 1);
        QCPGraph* upper = addCurve(*m_plot, tr("model ± 95 %"), t, high, QPen(kBand));
        upper->setBrush(kBand);
        upper->setChannelFillGraph(lower);
    }
    addCurve(*m_plot, tr("model's correction"), t, model, QPen(kModel, 1.2, Qt::DashLine));
    QCPGraph* step = addCurve(*m_plot, tr("offset sent"), t, sent, QPen(kSent, 2));
    step->setLineStyle(QCPGraph::lsStepLeft);
    step->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 4));
    m_plot->legend->setVisible(!updates.empty());
    m_plot->rescaleAxes();
    m_plot->yAxis->scaleRange(1.15, m_plot->yAxis->range().center());
    m_plot->replot();
}

}  // namespace driftlab::ui
