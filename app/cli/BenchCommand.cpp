// bench: the performance figures of docs/benchmarks.md, measured here and
// now on this machine (medians of several repetitions).
#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QProcess>
#include <QStandardPaths>
#include <algorithm>
#include <cmath>
#include <vector>

#include "app/cli/CliCommon.h"
#include "core/compensation/LiveThermalCompensation.h"
#include "core/diagnosis/Diagnosis.h"
#include "core/models/HeatTransferModel.h"
#include "core/physics/ScrewThermalModel.h"
#include "core/physics/SimulationThroughput.h"
#include "core/rig/CampaignSimulator.h"

namespace driftlab::cli {

/// ImportThroughput.cpp: `import` of a samples.csv of `megabytes` MB in a child process.
QJsonObject importFigures(int megabytes, int repetitions);
/// PushThroughput.cpp: `pushes` pushes of a 256-point table to the simulated controller.
QJsonObject pushFigures(int pushes);
/// LoggingThroughput.cpp; with `serverUrl`, also the upload rate into that server store.
QJsonObject loggingFigures(int repetitions, const QString& serverUrl = {});
void printLoggingLine(const QJsonObject& figures);
/// LiveReadLatency.cpp: device reading → reader of the live read path, µs.
QJsonObject liveReadFigures(int readings);
QJsonObject plotFigures(int repetitions);
void printPlotLine(const QJsonObject& figures);
/// ReportBench.cpp: the acceptance report's data and PDF drawing, ms.
QJsonObject reportFigures(int repetitions);
void printReportLine(const QJsonObject& figures);
/// ModelChoiceBench.cpp: `fit --model auto` and `arx` on spindle runs' drift, ms.
QJsonObject modelChoiceFigures(int repetitions);
void printModelChoiceLine(const QJsonObject& figures);
/// BatchThroughput.cpp: `batch` of `campaigns` simulated campaigns, -j1 and -j2.
QJsonObject batchFigures(int campaigns, int repetitions);
void printBatchLine(const QJsonObject& figures);

namespace {

/// Readings the live-read latency figure is the median and p99 of.
constexpr int kLiveReadings = 25000;

/// Heat-transfer identification on the five-run rig campaign: seconds, iterations, cost.
QJsonObject identificationFigures(int repetitions) {
    const Campaign campaign = rig::simulateCampaign(rig::RigSpec{});
    QStringList ids;
    for (const auto& r : campaign.runs) ids << r.id;
    const models::DatasetResult data = models::buildDataset(campaign, ids);
    if (!data.ok()) throw CliError(data.error);
    std::vector<double> seconds;
    models::FitSummary fit;
    for (int i = 0; i < repetitions; ++i) {
        models::HeatTransferModel model;
        QElapsedTimer timer;
        timer.start();
        fit = model.fit(data.runs);
        seconds.push_back(timer.nsecsElapsed() * 1e-9);
        if (!fit.success) throw CliError(fit.message);
        printProgress(QStringLiteral("identification"), (i + 1.0) / repetitions);
    }
    return {{QStringLiteral("identification_s"), median(seconds)},
            {QStringLiteral("identification_iterations"), fit.iterations},
            {QStringLiteral("identification_final_cost"),
             fit.metrics.at(QStringLiteral("final_cost"))}};
}

/// The full candidate library and the second pass on the five-run rig
/// campaign with two hidden effects, against one heat-transfer
/// identification of the same campaign (all five runs, the diagnosis's
/// tolerances), each repeated and interleaved so that the machine's load
/// moves both alike: their medians and the ratio of the medians.
QJsonObject diagnosisFigures(int repetitions) {
    rig::RigSpec spec;
    for (const QString& effect :
         {QStringLiteral("forced_convection=0.08"), QStringLiteral("frame_growth=3.5")}) {
        QString error;
        if (!rig::applyEffect(spec.effects, effect, &error)) throw CliError(error);
    }
    const Campaign campaign = rig::simulateCampaign(spec);
    QStringList ids;
    for (const auto& r : campaign.runs) ids << r.id;
    const models::DatasetResult data = models::buildDataset(campaign, ids);
    if (!data.ok()) throw CliError(data.error);
    std::vector<double> diagnosis_s, identification_s;
    for (int i = 0; i < repetitions; ++i) {
        diagnosis::DiagnosisOptions options;
        options.progress = [&](double f) {
            return printProgress(QStringLiteral("diagnosis"), (i + f) / repetitions);
        };
        QElapsedTimer timer;
        timer.start();
        const auto result = diagnosis::diagnose(campaign, options);
        if (!result.ok()) throw CliError(result.error);
        diagnosis_s.push_back(timer.nsecsElapsed() * 1e-9);
        models::HeatTransferOptions tolerances;  // as the diagnosis identifies
        tolerances.function_tolerance = 1e-6;
        tolerances.parameter_tolerance = 1e-5;
        models::HeatTransferModel model(tolerances);
        timer.restart();
        if (!model.fit(data.runs).success) throw CliError(QStringLiteral("identification failed"));
        identification_s.push_back(timer.nsecsElapsed() * 1e-9);
    }
    const double diagnosis = median(diagnosis_s), identification = median(identification_s);
    return {{QStringLiteral("diagnosis_s"), diagnosis},
            {QStringLiteral("diagnosis_identification_s"), identification},
            {QStringLiteral("diagnosis_over_identification"), diagnosis / identification},
            {QStringLiteral("diagnosis_repetitions"), repetitions}};
}

QString diagnosisLine(const QJsonObject& f) {
    return QStringLiteral(
               "diagnosis       candidates and second pass, 5 runs, 2 effects: %1 s = %2 × one "
               "heat-transfer identification of the same campaign (%3 s; medians of %4; "
               "target ≤ 8 ×)")
        .arg(f[QStringLiteral("diagnosis_s")].toDouble(), 0, 'f', 1)
        .arg(f[QStringLiteral("diagnosis_over_identification")].toDouble(), 0, 'f', 1)
        .arg(f[QStringLiteral("diagnosis_identification_s")].toDouble(), 0, 'f', 2)
        .arg(f[QStringLiteral("diagnosis_repetitions")].toInt());
}

/// One observer step of the live model plus a 128-point compensation table
/// update, µs: live compensation with an update due at every step, the worst case.
double onlineStepMicroseconds() {
    physics::BenchmarkCampaign campaign;
    compensation::LiveSettings settings;
    for (int i = 0; i < 128; ++i) settings.table_positions_mm.push_back(700.0 * i / 127);
    settings.offset_position_mm = 350;
    settings.max_change_um = 1;
    physics::StepConditions step;
    step.motion = campaign.motion;
    settings.update_interval_s = step.dt_s;
    compensation::LiveThermalCompensation live(campaign.parameters, 20, settings);
    const int steps = 20000;
    int updates = 0;
    QElapsedTimer timer;
    timer.start();
    for (int k = 0; k < steps; ++k) updates += live.step(step, MachineState::Idle).has_value();
    const double us = timer.nsecsElapsed() * 1e-3 / steps;
    // Checks the work was done (and keeps it from being optimised away).
    if (updates != steps || !std::isfinite(live.applied().offset_um))
        throw CliError(
            QStringLiteral("live compensation skipped an update or gave a non-finite "
                           "offset"));
    return us;
}

/// The same campaign in NumPy/SciPy (solve_banded), when Python has SciPy.
QJsonObject scipyFigures() {
    QFile script(QStringLiteral(":/bench/scipy_screw_bench.py"));
    if (!script.open(QIODevice::ReadOnly)) return {};
    const QByteArray code = script.readAll();
    for (const QString& python :
         {QStringLiteral("/usr/bin/python3"), QStandardPaths::findExecutable("python3")}) {
        if (python.isEmpty() || !QFile::exists(python)) continue;
        QProcess p;
        p.start(python, {QStringLiteral("-"), QStringLiteral("--repeat"), QStringLiteral("3")});
        p.write(code);
        p.closeWriteChannel();
        if (!p.waitForFinished(600'000) || p.exitCode() != 0) continue;
        return QJsonDocument::fromJson(p.readAllStandardOutput()).object();
    }
    return {};
}

void printLiveReadLine(const QJsonObject& live) {
    printLine(QStringLiteral("live read       device reading → waiting reader of the live buffer, "
                             "%1 readings in bursts: median %2 µs, p99 %3 µs")
                  .arg(live[QStringLiteral("live_read_readings")].toInt())
                  .arg(live[QStringLiteral("live_read_latency_median_us")].toDouble(), 0, 'f', 1)
                  .arg(live[QStringLiteral("live_read_latency_p99_us")].toDouble(), 0, 'f', 1));
}

void printPushLine(const QJsonObject& push) {
    printLine(QStringLiteral("push            256-point table to the simulated controller over "
                             "Modbus TCP, %1 pushes: median %2 ms, worst %3 ms")
                  .arg(push[QStringLiteral("push_256_count")].toInt())
                  .arg(push[QStringLiteral("push_256_median_ms")].toDouble(), 0, 'f', 2)
                  .arg(push[QStringLiteral("push_256_worst_ms")].toDouble(), 0, 'f', 2));
}

}  // namespace

int benchCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption repeat{QStringLiteral("repeat"),
                                    QStringLiteral("Repetitions per figure (median)."),
                                    QStringLiteral("N"), QStringLiteral("5")};
    const QCommandLineOption noPython{QStringLiteral("no-python"),
                                      QStringLiteral("Skip the SciPy comparison.")};
    const QCommandLineOption importMb{
        QStringLiteral("import-mb"),
        QStringLiteral("Size of the samples.csv the import figure uses, MB (0: skip)."),
        QStringLiteral("MB"), QStringLiteral("200")};
    const QCommandLineOption pushes{
        QStringLiteral("pushes"),
        QStringLiteral("Pushes of a 256-point table to the simulated controller (0: skip)."),
        QStringLiteral("N"), QStringLiteral("50")};
    const QCommandLineOption only{
        QStringLiteral("only"),
        QStringLiteral("Measure only this figure: push, online, logging, live-read, plot, "
                       "diagnosis, report, batch, model-choice."),
        QStringLiteral("FIGURE")};
    const QCommandLineOption server{
        QStringLiteral("db"),
        QStringLiteral("With --only logging: also the upload rate into this server store "
                       "(postgresql://USER@HOST[:PORT]/DB; it receives the benchmark's runs)."),
        QStringLiteral("URL")};
    parseArguments(parser, args, {repeat, noPython, importMb, pushes, only, server});
    const int pushCount = parser.value(pushes).toInt();
    if (parser.value(only) == QLatin1String("push")) {
        const QJsonObject figures = pushFigures(std::max(1, pushCount));
        endProgressLine();
        if (parser.isSet(QStringLiteral("json")))
            printJson(figures);
        else
            printPushLine(figures);
        return 0;
    }
    if (parser.value(only) == QLatin1String("logging")) {
        const QJsonObject figures =
            loggingFigures(std::max(1, parser.value(repeat).toInt()), parser.value(server));
        endProgressLine();
        if (parser.isSet(QStringLiteral("json")))
            printJson(figures);
        else
            printLoggingLine(figures);
        return 0;
    }
    if (parser.value(only) == QLatin1String("online")) {
        // The median of --repeat measurements of live compensation's step.
        std::vector<double> us;
        for (int i = 0; i < std::max(1, parser.value(repeat).toInt()); ++i)
            us.push_back(onlineStepMicroseconds());
        const double median_us = median(us);
        if (parser.isSet(QStringLiteral("json")))
            printJson({{QStringLiteral("online_step_us"), median_us}});
        else
            printLine(QStringLiteral("online model    %1 µs per observer step + 128-point table "
                                     "update (median of %2; target < 50 µs)")
                          .arg(median_us, 0, 'f', 2)
                          .arg(us.size()));
        return 0;
    }
    if (parser.value(only) == QLatin1String("live-read")) {
        const QJsonObject figures = liveReadFigures(kLiveReadings);
        endProgressLine();
        if (parser.isSet(QStringLiteral("json")))
            printJson(figures);
        else
            printLiveReadLine(figures);
        return 0;
    }
    if (parser.value(only) == QLatin1String("plot")) {
        const QJsonObject figures = plotFigures(std::max(3, parser.value(repeat).toInt()));
        endProgressLine();
        if (parser.isSet(QStringLiteral("json")))
            printJson(figures);
        else
            printPlotLine(figures);
        return 0;
    }
    if (parser.value(only) == QLatin1String("report")) {
        // Three by default: the data part takes tens of seconds.
        const QJsonObject figures =
            reportFigures(parser.isSet(repeat) ? std::max(1, parser.value(repeat).toInt()) : 3);
        endProgressLine();
        if (parser.isSet(QStringLiteral("json")))
            printJson(figures);
        else
            printReportLine(figures);
        return 0;
    }
    if (parser.value(only) == QLatin1String("model-choice")) {
        const QJsonObject figures = modelChoiceFigures(
            parser.isSet(repeat) ? std::max(1, parser.value(repeat).toInt()) : 3);
        endProgressLine();
        if (parser.isSet(QStringLiteral("json")))
            printJson(figures);
        else
            printModelChoiceLine(figures);
        return 0;
    }
    if (parser.value(only) == QLatin1String("batch")) {
        // Six campaigns: three rounds of two at a time, so -j2 is not flattered by a lone last
        // item.
        const QJsonObject figures = batchFigures(6, std::max(1, parser.value(repeat).toInt()));
        endProgressLine();
        if (parser.isSet(QStringLiteral("json")))
            printJson(figures);
        else
            printBatchLine(figures);
        return 0;
    }
    if (parser.value(only) == QLatin1String("diagnosis")) {
        const QJsonObject figures = diagnosisFigures(std::max(1, parser.value(repeat).toInt()));
        endProgressLine();
        if (parser.isSet(QStringLiteral("json")))
            printJson(figures);
        else
            printLine(diagnosisLine(figures));
        return 0;
    }
    if (parser.isSet(only))
        throw CliError(QStringLiteral("--only: '%1' is not a figure it can measure alone (push, "
                                      "online, logging, live-read, plot, report, batch, "
                                      "diagnosis, model-choice)")
                           .arg(parser.value(only)),
                       2);
    const int repetitions = std::max(1, parser.value(repeat).toInt());
    // First, while no other child has raised this process's memory high-water marks.
    const int megabytes = parser.value(importMb).toInt();
    const QJsonObject import =
        megabytes > 0 ? importFigures(megabytes, std::min(repetitions, 3)) : QJsonObject();

    printProgress(QStringLiteral("simulation"), 0);
    const physics::SimulationThroughput sim = physics::measureSimulationThroughput(repetitions);
    printProgress(QStringLiteral("simulation"), 1);
    QJsonObject figures{{QStringLiteral("simulation_cell_steps_per_s"), sim.cell_steps_per_s},
                        {QStringLiteral("simulation_8h_campaign_ms"), sim.campaign_ms},
                        {QStringLiteral("online_step_us"), onlineStepMicroseconds()}};
    const QJsonObject identification = identificationFigures(std::min(repetitions, 3));
    for (auto it = identification.begin(); it != identification.end(); ++it)
        figures[it.key()] = it.value();
    const QJsonObject diagnosis = diagnosisFigures(std::min(repetitions, 3));
    for (auto it = diagnosis.begin(); it != diagnosis.end(); ++it) figures[it.key()] = it.value();
    for (auto it = import.begin(); it != import.end(); ++it) figures[it.key()] = it.value();
    const QJsonObject push = pushCount > 0 ? pushFigures(pushCount) : QJsonObject();
    const QJsonObject logging = loggingFigures(std::min(repetitions, 3));
    for (auto it = logging.begin(); it != logging.end(); ++it) figures[it.key()] = it.value();
    for (auto it = push.begin(); it != push.end(); ++it) figures[it.key()] = it.value();
    const QJsonObject liveRead = liveReadFigures(kLiveReadings);
    for (auto it = liveRead.begin(); it != liveRead.end(); ++it) figures[it.key()] = it.value();
    const QJsonObject plot = plotFigures(repetitions);
    for (auto it = plot.begin(); it != plot.end(); ++it) figures[it.key()] = it.value();
    if (!parser.isSet(noPython)) {
        printProgress(QStringLiteral("scipy comparison"), 0);
        const QJsonObject scipy = scipyFigures();
        printProgress(QStringLiteral("scipy comparison"), 1);
        const double theirs = scipy[QStringLiteral("cell_steps_per_s")].toDouble();
        if (theirs > 0) {
            figures[QStringLiteral("scipy_cell_steps_per_s")] = theirs;
            figures[QStringLiteral("simulation_speedup_vs_scipy")] = sim.cell_steps_per_s / theirs;
        }
    }

    if (parser.isSet(QStringLiteral("json"))) {
        printJson(figures);
        return 0;
    }
    printLine(QStringLiteral("simulation      %1 million cell-steps/s; 8 h campaign, 200 cells, "
                             "1 s steps: %2 ms (target ≥ 200 million, < 30 ms)")
                  .arg(sim.cell_steps_per_s / 1e6, 0, 'f', 0)
                  .arg(sim.campaign_ms, 0, 'f', 1));
    if (figures.contains(QStringLiteral("scipy_cell_steps_per_s")))
        printLine(
            QStringLiteral("                SciPy solve_banded: %1 million cell-steps/s "
                           "(%2× slower)")
                .arg(figures[QStringLiteral("scipy_cell_steps_per_s")].toDouble() / 1e6, 0, 'f', 1)
                .arg(figures[QStringLiteral("simulation_speedup_vs_scipy")].toDouble(), 0, 'f', 0));
    printLoggingLine(figures);
    printLine(QStringLiteral("online model    %1 µs per observer step + 128-point table (target "
                             "< 50 µs)")
                  .arg(figures[QStringLiteral("online_step_us")].toDouble(), 0, 'f', 2));
    printLine(QStringLiteral("identification  heat-transfer on 5 runs: %1 s, %2 iterations, "
                             "final cost %3 (target < 2 s)")
                  .arg(figures[QStringLiteral("identification_s")].toDouble(), 0, 'f', 2)
                  .arg(figures[QStringLiteral("identification_iterations")].toInt())
                  .arg(figures[QStringLiteral("identification_final_cost")].toDouble(), 0, 'g', 4));
    printLine(diagnosisLine(figures));
    if (!import.isEmpty())
        printLine(
            QStringLiteral("import          %1 MB samples.csv, %2 million samples: %3 million "
                           "samples/s, peak memory %4 MB = %5 × the file (target ≥ 1.5 "
                           "million, ≤ 1.5 ×)")
                .arg(import[QStringLiteral("import_csv_mb")].toDouble(), 0, 'f', 0)
                .arg(import[QStringLiteral("import_samples")].toDouble() / 1e6, 0, 'f', 1)
                .arg(import[QStringLiteral("import_samples_per_s")].toDouble() / 1e6, 0, 'f', 2)
                .arg(import[QStringLiteral("import_peak_rss_mb")].toDouble(), 0, 'f', 0)
                .arg(import[QStringLiteral("import_peak_memory_ratio")].toDouble(), 0, 'f', 2));
    if (!push.isEmpty()) printPushLine(push);
    printLiveReadLine(liveRead);
    printPlotLine(plot);
    return 0;
}

}  // namespace driftlab::cli
