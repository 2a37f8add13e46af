#include "ui/widgets/PredictionPlotWidget.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <algorithm>
#include <numeric>
#include <set>

#include "ui/widgets/PlotView.h"

namespace driftlab::ui {

PredictionPlotWidget::PredictionPlotWidget(QWidget* parent) : QWidget(parent) {
    m_run = new QComboBox(this);
    m_target = new QComboBox(this);
    m_plot = new PlotView(this);
    auto* choice = new QHBoxLayout;
    choice->addWidget(new QLabel(tr("Test run"), this));
    choice->addWidget(m_run);
    choice->addWidget(new QLabel(tr("Target"), this));
    choice->addWidget(m_target);
    choice->addStretch();
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(choice);
    layout->addWidget(m_plot, 1);
    connect(m_run, &QComboBox::currentIndexChanged, this, [this] {
        fillTargets();
        redraw();
    });
    connect(m_target, &QComboBox::currentIndexChanged, this, &PredictionPlotWidget::redraw);
    clear(tr("Fit a model with test runs to compare its predictions with the measurements."));
}

void PredictionPlotWidget::setPredictions(const QString& model, std::vector<RunPrediction> runs) {
    m_model = model;
    m_runs = std::move(runs);
    {
        const QSignalBlocker blocker(m_run);
        m_run->clear();
        for (const RunPrediction& run : m_runs) m_run->addItem(run.run_id);
    }
    fillTargets();
    redraw();
}

void PredictionPlotWidget::clear(const QString& why) {
    m_runs.clear();
    const QSignalBlocker runBlocker(m_run), targetBlocker(m_target);
    m_run->clear();
    m_target->clear();
    m_plot->showMessage(why);
}

void PredictionPlotWidget::fillTargets() {
    const QSignalBlocker blocker(m_target);
    m_target->clear();
    const int k = m_run->currentIndex();
    if (k < 0 || k >= int(m_runs.size())) return;
    std::set<double> targets;
    for (const auto& o : m_runs[std::size_t(k)].observations) targets.insert(o.position_mm);
    for (double x : targets) m_target->addItem(tr("%1 mm").arg(x, 0, 'f', 1), x);
    // The far end shows the largest thermal error of a feed axis.
    m_target->setCurrentIndex(m_target->count() - 1);
}

CurvePlot PredictionPlotWidget::predictionPlot(const QString& model, const RunPrediction& run,
                                               double position_mm) {
    Curve measured{tr("measured"), {}, {}, true};
    Curve predicted{tr("%1 prediction").arg(model), {}, {}, false};
    Curve residual{tr("residual (measured − model)"), {}, {}, false};
    Curve upper{tr("prediction interval (95 %)"), {}, {}, false, -1};
    Curve lower{QString(), {}, {}, false, 3};  // closes the band of `upper`, curve 3
    const bool interval = run.interval_um.size() == run.observations.size();
    std::vector<std::size_t> order(run.observations.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return run.observations[a].time_s < run.observations[b].time_s;
    });
    for (std::size_t j : order) {
        const auto& o = run.observations[j];
        if (o.position_mm != position_mm || j >= run.predicted_um.size()) continue;
        const double t_h = o.time_s / 3600;
        measured.x.push_back(t_h);
        measured.y.push_back(o.error_um);
        predicted.x.push_back(t_h);
        predicted.y.push_back(run.predicted_um[j]);
        residual.x.push_back(t_h);
        residual.y.push_back(o.error_um - run.predicted_um[j]);
        if (interval) {
            upper.x.push_back(t_h);
            upper.y.push_back(run.predicted_um[j] + run.interval_um[j]);
            lower.x.push_back(t_h);
            lower.y.push_back(run.predicted_um[j] - run.interval_um[j]);
        }
    }
    std::vector<Curve> curves{measured, predicted, residual};
    if (interval) curves.insert(curves.end(), {upper, lower});
    return {tr("%1: thermal error at %2 mm, RMS %3 µm")
                .arg(run.run_id)
                .arg(position_mm, 0, 'f', 1)
                .arg(run.score.rms_um, 0, 'f', 2),
            tr("time (h)"), tr("thermal error (µm)"), curves};
}

void PredictionPlotWidget::redraw() {
    const int k = m_run->currentIndex();
    if (k < 0 || k >= int(m_runs.size()) || m_target->currentIndex() < 0) return;
    const RunPrediction& run = m_runs[std::size_t(k)];
    if (run.predicted_um.size() != run.observations.size()) {
        m_plot->showMessage(tr("%1: %2").arg(run.run_id, run.score.error));
        return;
    }
    m_plot->showCurves(predictionPlot(m_model, run, m_target->currentData().toDouble()));
}

}  // namespace driftlab::ui
