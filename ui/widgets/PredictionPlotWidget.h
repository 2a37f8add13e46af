#pragma once
// Predictions against measurements: for a chosen test run and axis target,
// the measured thermal error, the model's prediction and the residual over
// time (both directions of travel).

#include <QWidget>
#include <vector>

#include "ui/plots/PngPlots.h"
#include "ui/shell/FitJob.h"

class QComboBox;

namespace driftlab::ui {

class PlotView;

class PredictionPlotWidget : public QWidget {
    Q_OBJECT
public:
    explicit PredictionPlotWidget(QWidget* parent = nullptr);

    void setPredictions(const QString& model, std::vector<RunPrediction> runs);
    void clear(const QString& why);

    QComboBox* runBox() const { return m_run; }
    QComboBox* targetBox() const { return m_target; }
    PlotView* plot() const { return m_plot; }

    /// The plot of run `runIndex` at target `position_mm` (drift: position 0).
    static CurvePlot predictionPlot(const QString& model, const RunPrediction& run,
                                    double position_mm);

private:
    void fillTargets();
    void redraw();

    QComboBox* m_run;
    QComboBox* m_target;
    PlotView* m_plot;
    QString m_model;
    std::vector<RunPrediction> m_runs;
};

}  // namespace driftlab::ui
