#pragma once
// A plot on a page: the MapPlot / CurvePlot descriptions the PNG export draws
// (ui/plots), drawn into a QCustomPlot widget, or a line saying why there is
// nothing to show.

#include <QWidget>

#include "ui/plots/PngPlots.h"

class QCustomPlot;
class QLabel;

namespace driftlab::ui {

class PlotView : public QWidget {
    Q_OBJECT
public:
    explicit PlotView(QWidget* parent = nullptr);

    void showMap(const MapPlot& plot);
    void showCurves(const CurvePlot& plot);
    /// No plot: `message` instead (e.g. "fit a model to see its predictions").
    void showMessage(const QString& message);
    /// The number of curves shown (0 for a map or a message).
    int curveCount() const;

private:
    QCustomPlot* freshPlot();

    QCustomPlot* m_plot = nullptr;
    QLabel* m_message = nullptr;
    int m_curves = 0;
};

}  // namespace driftlab::ui
