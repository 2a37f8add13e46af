#include "ui/widgets/PlotView.h"

#include <qcustomplot.h>

#include <QLabel>
#include <QVBoxLayout>

#include "ui/plots/PlotDrawing.h"

namespace driftlab::ui {

PlotView::PlotView(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_message = new QLabel(this);
    m_message->setAlignment(Qt::AlignCenter);
    m_message->setWordWrap(true);
    layout->addWidget(m_message);
    setMinimumSize(240, 180);
}

QCustomPlot* PlotView::freshPlot() {
    // A plot's layout (title row, colour scale) is built once per picture, so a
    // new picture gets a new widget.
    delete m_plot;
    m_plot = new QCustomPlot(this);
    layout()->addWidget(m_plot);
    m_message->hide();
    return m_plot;
}

void PlotView::showMap(const MapPlot& plot) {
    if (const QString problem = mapProblem(plot); !problem.isEmpty()) {
        showMessage(tr("%1: %2").arg(plot.title, problem));
        return;
    }
    drawMap(*freshPlot(), plot);
    m_curves = 0;
    m_plot->replot();
}

void PlotView::showCurves(const CurvePlot& plot) {
    if (const QString problem = curvesProblem(plot); !problem.isEmpty()) {
        showMessage(tr("%1: %2").arg(plot.title, problem));
        return;
    }
    drawCurves(*freshPlot(), plot);
    m_curves = int(plot.curves.size());
    m_plot->replot();
}

void PlotView::showMessage(const QString& message) {
    delete m_plot;
    m_plot = nullptr;
    m_curves = 0;
    m_message->setText(message);
    m_message->show();
}

int PlotView::curveCount() const {
    return m_curves;
}

}  // namespace driftlab::ui
