#include "ui/widgets/CompensationPlot.h"

#include <qcustomplot.h>

#include <QVBoxLayout>

namespace driftlab::ui {
namespace {

QVector<double> toVector(const std::vector<double>& values) {
    return QVector<double>(values.begin(), values.end());
}

QCPGraph* addCurve(QCustomPlot& plot, const QString& name, const QVector<double>& x,
                   const QVector<double>& y, const QPen& pen, bool markers) {
    QCPGraph* graph = plot.addGraph();
    graph->setName(name);
    graph->setData(x, y, true);
    graph->setPen(pen);
    if (markers) graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 5));
    return graph;
}

}  // namespace

CompensationPlot::CompensationPlot(QWidget* parent)
    : QWidget(parent), m_plot(new QCustomPlot(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    m_plot->xAxis->setLabel(tr("Position (mm)"));
    m_plot->yAxis->setLabel(tr("Correction (µm)"));
    m_plot->legend->setVisible(true);
    m_plot->legend->setFont(QFont(font().family(), 8));
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignBottom | Qt::AlignLeft);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    setMinimumSize(320, 220);
}

void CompensationPlot::clear() {
    m_plot->clearGraphs();
    m_plot->replot();
}

int CompensationPlot::graphCount() const {
    return m_plot->graphCount();
}

void CompensationPlot::show(const compensation::CompensationTable& table,
                            const std::optional<push::TableChange>& change) {
    m_plot->clearGraphs();
    const QVector<double> x = toVector(table.position_mm);
    const QColor plus(0x1f, 0x5f, 0xbf), minus(0xc0, 0x30, 0x30), active(0x70, 0x70, 0x70);
    // The band of the corrections' expanded uncertainty (95 %) around the
    // first column: where the table's values may lie.
    if (table.uncertainty_um.size() == table.size()) {
        QVector<double> low, high;
        for (std::size_t i = 0; i < table.size(); ++i) {
            low << table.correction_plus_um[i] - table.uncertainty_um[i];
            high << table.correction_plus_um[i] + table.uncertainty_um[i];
        }
        const QColor band(0x1f, 0x5f, 0xbf, 40);
        QCPGraph* lower = addCurve(*m_plot, tr("uncertainty (95 %)"), x, low, QPen(band), false);
        QCPGraph* upper = addCurve(*m_plot, QString(), x, high, QPen(band), false);
        upper->setBrush(band);
        upper->setChannelFillGraph(lower);
        m_plot->legend->removeItem(m_plot->legend->itemCount() - 1);
    }
    if (table.bidirectional) {
        addCurve(*m_plot, tr("correction +"), x, toVector(table.correction_plus_um), QPen(plus, 2),
                 true);
        addCurve(*m_plot, tr("correction −"), x, toVector(table.correction_minus_um),
                 QPen(minus, 2), true);
    } else {
        addCurve(*m_plot, tr("correction"), x, toVector(table.correction_plus_um), QPen(plus, 2),
                 true);
    }
    if (change) {
        QPen dashed(active, 1.5, Qt::DashLine);
        addCurve(*m_plot, tr("controller's active table"), x,
                 toVector(change->active.correction_plus_um), dashed, false);
        if (table.bidirectional) {
            dashed.setStyle(Qt::DotLine);
            addCurve(*m_plot, tr("active −"), x, toVector(change->active.correction_minus_um),
                     dashed, false);
        }
        addCurve(*m_plot, tr("change a push makes (+)"), x, toVector(change->change_plus_um),
                 QPen(QColor(0xe0, 0x80, 0x00), 1.5), true)
            ->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDiamond, 5));
    }
    m_plot->rescaleAxes();
    // A little air around the curves so the end points and the legend read.
    m_plot->xAxis->scaleRange(1.05, m_plot->xAxis->range().center());
    m_plot->yAxis->scaleRange(1.25, m_plot->yAxis->range().center());
    m_plot->replot();
}

}  // namespace driftlab::ui
