#include "ui/widgets/Iso230_2Plot.h"

#include <qcustomplot.h>

#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace driftlab::ui {

Iso230_2Plot::Iso230_2Plot(QWidget* parent) : QWidget(parent), m_plot(new QCustomPlot(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    m_plot->xAxis->setLabel(tr("Target position (mm)"));
    m_plot->yAxis->setLabel(tr("Positional deviation, actual − target (µm)"));
    m_plot->legend->setVisible(true);
    m_plot->legend->setFont(QFont(font().family(), 8));
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    setMinimumSize(320, 220);
}

void Iso230_2Plot::clear() {
    m_plot->clearPlottables();
    m_plot->replot();
}

int Iso230_2Plot::graphCount() const {
    return m_plot->graphCount();
}

void Iso230_2Plot::render(QCPPainter* painter, int width, int height) {
    m_plot->toPainter(painter, width, height);
}

void Iso230_2Plot::show(const iso::Evaluation& evaluation,
                        std::optional<double> accuracyTolerance_um) {
    m_plot->clearPlottables();
    const double k = evaluation.settings.coverage_factor;
    struct Direction {
        QString name;
        QColor colour;
        double iso::TargetResult::*mean;
        double iso::TargetResult::*s;
        QCPScatterStyle::ScatterShape shape;
    };
    const Direction directions[] = {
        {tr("x̄↑ (+ approach)"), QColor(0x1f, 0x5f, 0xbf), &iso::TargetResult::mean_up_um,
         &iso::TargetResult::s_up_um, QCPScatterStyle::ssTriangle},
        {tr("x̄↓ (− approach)"), QColor(0xc0, 0x30, 0x30), &iso::TargetResult::mean_down_um,
         &iso::TargetResult::s_down_um, QCPScatterStyle::ssTriangleInverted}};
    for (const Direction& d : directions) {
        QVector<double> x, y, spread;
        for (const iso::TargetResult& t : evaluation.targets) {
            if (!std::isfinite(t.*d.mean)) continue;
            x << t.target_mm;
            y << t.*d.mean;
            spread << (std::isfinite(t.*d.s) ? k * (t.*d.s) : 0.0);
        }
        if (x.isEmpty()) continue;
        QCPGraph* graph = m_plot->addGraph();
        graph->setName(QStringLiteral("%1 ± %2s").arg(d.name).arg(k));
        graph->setData(x, y, true);
        graph->setPen(QPen(d.colour, 2));
        graph->setScatterStyle(QCPScatterStyle(d.shape, d.colour, 7));
        auto* bars = new QCPErrorBars(m_plot->xAxis, m_plot->yAxis);
        bars->removeFromLegend();
        bars->setDataPlottable(graph);
        bars->setData(spread);
        bars->setPen(QPen(d.colour, 1));
        bars->setWhiskerWidth(8);
    }
    // The band the upper and lower limits span, as a light fill for reading A.
    QVector<double> x, upper, lower;
    for (const iso::TargetResult& t : evaluation.targets) {
        double hi = -INFINITY, lo = INFINITY;
        for (const Direction& d : directions) {
            if (!std::isfinite(t.*d.mean)) continue;
            const double s = std::isfinite(t.*d.s) ? k * (t.*d.s) : 0.0;
            hi = std::max(hi, t.*d.mean + s);
            lo = std::min(lo, t.*d.mean - s);
        }
        if (!std::isfinite(hi)) continue;
        x << t.target_mm;
        upper << hi;
        lower << lo;
    }
    if (!x.isEmpty()) {
        QCPGraph* low = m_plot->addGraph();
        low->setData(x, lower, true);
        low->setPen(Qt::NoPen);
        low->removeFromLegend();
        QCPGraph* high = m_plot->addGraph();
        high->setData(x, upper, true);
        high->setPen(Qt::NoPen);
        high->setBrush(QColor(0x80, 0x80, 0x80, 40));
        high->setChannelFillGraph(low);
        high->setName(tr("span of x̄ ± %1s (A)").arg(k));
        if (accuracyTolerance_um) {
            const double centre_um = (*std::max_element(upper.begin(), upper.end()) +
                                      *std::min_element(lower.begin(), lower.end())) /
                                     2;
            const QVector<double> ends{x.front(), x.back()};
            for (const double side : {-1.0, 1.0}) {
                QCPGraph* line = m_plot->addGraph();
                const double y_um = centre_um + side * *accuracyTolerance_um / 2;
                line->setData(ends, {y_um, y_um}, true);
                line->setPen(QPen(QColor(0x20, 0x90, 0x40), 1.5, Qt::DashLine));
                if (side < 0)
                    line->removeFromLegend();
                else
                    line->setName(tr("tolerance of A: %1 µm").arg(*accuracyTolerance_um));
            }
        }
    }
    m_plot->rescaleAxes();
    m_plot->xAxis->scaleRange(1.06, m_plot->xAxis->range().center());
    m_plot->yAxis->scaleRange(1.3, m_plot->yAxis->range().center());
    m_plot->replot();
}

}  // namespace driftlab::ui
