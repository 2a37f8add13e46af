// bench: `fit --model auto` on the z drift of six simulated spindle runs,
// trained on SP1–SP3: the whole choice (every family cross-validated, the
// winner refitted: auto_fit_ms) and the lagged-sensors model alone (arx_fit_ms),
// medians.
#include <QElapsedTimer>
#include <algorithm>
#include <vector>

#include "bench/BenchFigures.h"
#include "core/models/AutoModel.h"
#include "core/models/LaggedSensorsModel.h"
#include "core/rig/CampaignSimulator.h"

namespace driftlab::bench {
namespace {

/// Fit time, ms; throws CliError when the fit fails.
double fitMs(models::ThermalErrorModel& model, const std::vector<models::RunData>& runs) {
    QElapsedTimer timer;
    timer.start();
    const models::FitSummary fit = model.fit(runs);
    const double ms = double(timer.nsecsElapsed()) * 1e-6;
    if (!fit.success) throw CliError(fit.message);
    return ms;
}

}  // namespace

QJsonObject modelChoiceFigures(int repetitions) {
    rig::RigSpec spec;
    spec.runs.clear();
    spec.spindle_runs = 6;
    const Campaign campaign = rig::simulateCampaign(spec);
    models::DatasetOptions options;
    options.target_channel = QStringLiteral("D_z");
    const models::DatasetResult data =
        models::buildDataset(campaign, {"SP1", "SP2", "SP3"}, options);
    if (!data.ok()) throw CliError(data.error);
    std::vector<double> autoMs, arxMs;
    QString chosen;
    for (int i = 0; i < repetitions; ++i) {
        models::AutoModel automatic;
        autoMs.push_back(fitMs(automatic, data.runs));
        chosen = automatic.chosen();
        models::LaggedSensorsModel arx;
        arxMs.push_back(fitMs(arx, data.runs));
        printProgress(QStringLiteral("model choice"), (i + 1.0) / repetitions);
    }
    return {{QStringLiteral("auto_fit_ms"), median(autoMs)},
            {QStringLiteral("arx_fit_ms"), median(arxMs)},
            {QStringLiteral("auto_chose"), chosen}};
}

void printModelChoiceLine(const QJsonObject& figures) {
    printLine(QStringLiteral("model choice    auto on 3 spindle runs' z drift (chose %1): %2 ms, "
                             "arx alone %3 ms (medians)")
                  .arg(figures[QStringLiteral("auto_chose")].toString())
                  .arg(figures[QStringLiteral("auto_fit_ms")].toDouble(), 0, 'f', 0)
                  .arg(figures[QStringLiteral("arx_fit_ms")].toDouble(), 0, 'f', 0));
}

}  // namespace driftlab::bench
