// simulate: a whole campaign from the simulated rig (docs/physics.md and docs/acquisition.md).
#include <QDir>
#include <QJsonArray>
#include <map>
#include <memory>

#include "app/cli/CliCommon.h"
#include "core/bundle/BundleWriter.h"
#include "core/rig/CampaignSimulator.h"
#include "core/rig/ModuleOutage.h"
#include "ui/plots/ScrewStatePlots.h"

namespace driftlab::cli {

int simulateCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption out{QStringLiteral("out"), QStringLiteral("Bundle folder to write."),
                                 QStringLiteral("DIR")};
    const QCommandLineOption effect{
        QStringLiteral("effect"),
        QStringLiteral("Hide an effect, ID=VALUE (repeatable): forced_convection=h1, "
                       "nut_heat_exponent=n, motor_heat=W/(N·m)², sensor_lag:CH=s, "
                       "sensor_offset:CH=K, air_refraction=fraction, frame_growth=µm/K."),
        QStringLiteral("ID=VALUE")};
    const QCommandLineOption seed{QStringLiteral("seed"),
                                  QStringLiteral("Random seed (noise, room)."), QStringLiteral("N"),
                                  QStringLiteral("1")};
    const QCommandLineOption runs{
        QStringLiteral("runs"),
        QStringLiteral("Moving states to simulate, e.g. S1,S4 (default: S1–S5)."),
        QStringLiteral("IDS")};
    const QCommandLineOption spindle{QStringLiteral("spindle"),
                                     QStringLiteral("Add an ISO 230-3 spindle run (SP1).")};
    const QCommandLineOption spindleRuns{
        QStringLiteral("spindle-runs"),
        QStringLiteral("Add N spindle runs SP1…SPN, each with its own speed programme (1–9)."),
        QStringLiteral("N")};
    const QCommandLineOption outage{
        QStringLiteral("outage"),
        QStringLiteral("The temperature module does not answer in run RUN from FROM to TO s of "
                       "run time: its columns are empty there (repeatable), e.g. S3@3000-3300."),
        QStringLiteral("RUN@FROM-TO")};
    const QCommandLineOption plots{
        QStringLiteral("plots"),
        QStringLiteral("Write PNG plots of the first run's true screw state into DIR."),
        QStringLiteral("DIR")};
    parseArguments(parser, args, {out, effect, seed, runs, spindle, spindleRuns, outage, plots},
                   {{}, {}, {}, {out}});

    rig::RigSpec spec;
    bool seedOk = false;
    spec.seed = parser.value(seed).toUInt(&seedOk);
    if (!seedOk) throw CliError(QStringLiteral("--seed: not a non-negative integer"), 2);
    for (const QString& assignment : parser.values(effect)) {
        QString error;
        if (!rig::applyEffect(spec.effects, assignment, &error)) throw CliError(error, 2);
    }
    if (parser.isSet(runs)) {
        std::vector<rig::MovingStateRun> chosen;
        for (const QString& id : parser.value(runs).split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            auto it = std::find_if(spec.runs.begin(), spec.runs.end(),
                                   [&](const auto& r) { return r.id == id.trimmed(); });
            if (it == spec.runs.end())
                throw CliError(QStringLiteral("--runs: no moving state '%1' (S1…S5)").arg(id), 2);
            chosen.push_back(*it);
        }
        spec.runs = chosen;
    }
    spec.spindle_runs = parser.isSet(spindle) ? 1 : 0;
    if (parser.isSet(spindleRuns)) {
        bool ok = false;
        spec.spindle_runs = parser.value(spindleRuns).toInt(&ok);
        if (!ok || spec.spindle_runs < 1 || spec.spindle_runs > 9)
            throw CliError(QStringLiteral("--spindle-runs: not a number of runs from 1 to 9"), 2);
    }
    for (const QString& text : parser.values(outage)) {
        QString error;
        const auto parsed = rig::parseModuleOutage(text, &error);
        if (!parsed) throw CliError(QStringLiteral("--outage: ") + error, 2);
        QStringList ids;
        for (const auto& r : spec.runs) ids << r.id;
        for (int k = 1; k <= spec.spindle_runs; ++k) ids << QStringLiteral("SP%1").arg(k);
        if (!ids.contains(parsed->run_id))
            throw CliError(QStringLiteral("--outage: '%1': the campaign has no run '%2' (its runs: "
                                          "%3)")
                               .arg(text, parsed->run_id, ids.join(QStringLiteral(", "))),
                           2);
        spec.module_outages.push_back(*parsed);
    }

    rig::SimulationCallbacks callbacks;
    callbacks.progress = [](double f) { return printProgress(QStringLiteral("simulating"), f); };
    std::unique_ptr<ui::ScrewStateRecorder> recorder;
    QString plottedRun;
    if (parser.isSet(plots) && !spec.runs.empty()) {
        plottedRun = spec.runs.front().id;
        recorder = std::make_unique<ui::ScrewStateRecorder>(1800, spec.travel_mm.from_mm,
                                                            spec.travel_mm.to_mm);
        callbacks.sample = [&](const QString& run, const physics::ScrewThermalModel& screw) {
            if (run == plottedRun) recorder->record(screw);
        };
    }

    Campaign campaign;
    try {
        campaign = rig::simulateCampaign(spec, callbacks);
    } catch (const std::invalid_argument& e) {
        throw CliError(QString::fromStdString(e.what()));
    }
    const QString dir = parser.value(out);
    if (auto error = bundle::writeBundle(campaign, dir, bundle::ExistingBundle::Replace))
        throw CliError(error->toString());

    QJsonArray writtenPlots;
    if (recorder) {
        QDir().mkpath(parser.value(plots));
        const QDir plotDir(parser.value(plots));
        const QString title = QStringLiteral("%1: %2 mm/min over %3–%4 mm (simulated truth)")
                                  .arg(plottedRun)
                                  .arg(spec.runs.front().feed_mm_min)
                                  .arg(spec.runs.front().range_mm.from_mm)
                                  .arg(spec.runs.front().range_mm.to_mm);
        const QString map = plotDir.filePath(plottedRun + QStringLiteral("-screw-temperature.png"));
        const QString curves = plotDir.filePath(plottedRun + QStringLiteral("-thermal-error.png"));
        QString error;
        if (!recorder->saveTemperatureMap(map, title, &error) ||
            !recorder->saveThermalErrorCurves(curves, title, &error))
            throw CliError(error);
        writtenPlots << map << curves;
    }

    if (parser.isSet(QStringLiteral("json"))) {
        QJsonArray runIds;
        for (const auto& r : campaign.runs) runIds << r.id;
        printJson({{QStringLiteral("out"), dir},
                   {QStringLiteral("runs"), runIds},
                   {QStringLiteral("seed"), static_cast<qint64>(spec.seed)},
                   {QStringLiteral("plots"), writtenPlots}});
    } else {
        printLine(dir);
    }
    return 0;
}

}  // namespace driftlab::cli
