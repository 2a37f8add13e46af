#include "app/cli/ThermalProfile.h"

#include <algorithm>
#include <cmath>

#include "app/cli/CliCommon.h"
#include "core/models/ModelFactory.h"

namespace driftlab::cli {
namespace {

const QCommandLineOption kModel{
    QStringLiteral("model"),
    QStringLiteral("Add this model's thermal error at the state of --at to the cold error."),
    QStringLiteral("NAME")};
const QCommandLineOption kTrain{QStringLiteral("train"),
                                QStringLiteral("Runs the model is fitted on (default: the run of "
                                               "--at is not among them; the first other run)."),
                                QStringLiteral("R,..")};
const QCommandLineOption kAt{
    QStringLiteral("at"),
    QStringLiteral("The thermal state: a run and a time in it, RUN@SECONDS (e.g. S3@3600)."),
    QStringLiteral("RUN@S")};

/// Where the profile is evaluated: one point per millimetre at most, at least
/// 64, then linear in between (the heat-transfer model simulates the whole run
/// per call, so it is called once).
constexpr int kProfilePoints = 257;

}  // namespace

QList<QCommandLineOption> thermalProfileOptions() {
    return {kModel, kTrain, kAt};
}

bool wantsThermalProfile(const QCommandLineParser& parser) {
    return parser.isSet(kModel) || parser.isSet(kAt);
}

ThermalProfile thermalProfile(const QCommandLineParser& parser, const Campaign& campaign,
                              double from_mm, double to_mm) {
    if (!parser.isSet(kModel) || !parser.isSet(kAt))
        throw CliError(QStringLiteral("a thermal state needs both --model and --at RUN@SECONDS"),
                       2);
    const QString at = parser.value(kAt);
    const QStringList parts = at.split(QLatin1Char('@'));
    bool ok = parts.size() == 2;
    const double time_s = ok ? parts[1].toDouble(&ok) : 0;
    if (!ok || !std::isfinite(time_s) || time_s < 0)
        throw CliError(
            QStringLiteral("--at: '%1' is not RUN@SECONDS (a run and a time in it)").arg(at), 2);
    const QString stateRun = parts[0];
    QStringList train = runList(parser.value(kTrain));
    refuseOverlappingRuns(train, {stateRun});
    if (train.isEmpty())
        for (const Run& run : campaign.runs)
            if (run.id != stateRun && isFeedAxisRun(run.kind) && !run.positioning.empty()) {
                train << run.id;
                break;
            }
    if (train.isEmpty()) throw CliError(QStringLiteral("--train: no run to fit the model on"), 2);

    auto model = models::makeModel(parser.value(kModel));
    if (!model)
        throw CliError(QStringLiteral("--model: '%1' is not a model (%2)")
                           .arg(parser.value(kModel), models::modelNames().join(", ")),
                       2);
    models::DatasetResult data = models::buildDataset(campaign, train + QStringList{stateRun});
    if (!data.ok()) throw CliError(data.error);
    const models::RunData state = data.runs.back();
    data.runs.pop_back();
    double end_s = 0;
    for (const auto& o : state.observations) end_s = std::max(end_s, o.time_s);
    if (!state.motion.empty()) end_s = std::max(end_s, state.motion.back().end_s);
    if (time_s > end_s)
        throw CliError(QStringLiteral("--at: run %1 ends at %2 s, before %3 s")
                           .arg(stateRun)
                           .arg(end_s)
                           .arg(time_s),
                       2);
    printProgress(QStringLiteral("fitting ") + model->name(), 0);
    const models::FitSummary fit = model->fit(data.runs);
    printProgress(QStringLiteral("fitting ") + model->name(), 1);
    if (!fit.success) throw CliError(fit.message);

    ThermalProfile profile;
    profile.from_mm = from_mm;
    profile.to_mm = to_mm;
    profile.fixed_end_mm = state.fixedEnd_mm();
    std::vector<models::PredictionPoint> points;
    for (int i = 0; i < kProfilePoints; ++i)
        points.push_back({time_s, from_mm + (to_mm - from_mm) * i / (kProfilePoints - 1)});
    const models::Prediction predicted = model->predict(state, points);
    if (!predicted.ok()) throw CliError(QStringLiteral("--at %1: ").arg(at) + predicted.error);
    std::vector<double> x_mm, e_um;
    for (std::size_t i = 0; i < points.size(); ++i) {
        x_mm.push_back(points[i].position_mm);
        e_um.push_back(predicted.error_um[i]);
    }
    profile.error_um = [x_mm, e_um](double x) {
        if (x <= x_mm.front()) return e_um.front();
        if (x >= x_mm.back()) return e_um.back();
        const auto hi = std::size_t(std::upper_bound(x_mm.begin(), x_mm.end(), x) - x_mm.begin());
        const double f = (x - x_mm[hi - 1]) / (x_mm[hi] - x_mm[hi - 1]);
        return e_um[hi - 1] + f * (e_um[hi] - e_um[hi - 1]);
    };
    profile.description = QStringLiteral("%1 fitted on %2, at %3 t = %4 s")
                              .arg(model->name(), train.join(QLatin1Char(',')), stateRun)
                              .arg(time_s);
    return profile;
}

}  // namespace driftlab::cli
