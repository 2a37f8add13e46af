// driftlab-bench: the performance figures of docs/benchmarks.md, measured here
// and now on this machine (medians of several repetitions). Figures, not
// verdicts: each line names its target, the reader judges.
#include <glog/logging.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <algorithm>
#include <cstdio>
#include <functional>
#include <vector>

#include "bench/BenchFigures.h"
#include "bench/SimulationThroughput.h"

namespace driftlab::bench {

namespace {

/// Readings the live-read latency figure is the median and p99 of.
constexpr int kLiveReadings = 25000;

/// A figure --only measures alone: its name, its measurement, its line.
struct SingleFigure {
    const char* name;
    std::function<QJsonObject()> measure;
    std::function<void(const QJsonObject&)> print;
};

/// The median of `repetitions` measurements of live compensation's step.
QJsonObject onlineFigures(int repetitions) {
    std::vector<double> us;
    for (int i = 0; i < repetitions; ++i) us.push_back(onlineStepMicroseconds());
    return {{QStringLiteral("online_step_us"), median(us)},
            {QStringLiteral("online_repetitions"), repetitions}};
}

void printOnlineLine(const QJsonObject& f) {
    printLine(QStringLiteral("online model    %1 µs per observer step + 128-point table update "
                             "(median of %2; target < 50 µs)")
                  .arg(f[QStringLiteral("online_step_us")].toDouble(), 0, 'f', 2)
                  .arg(f[QStringLiteral("online_repetitions")].toInt()));
}

}  // namespace

QString cliExecutable() {
    // Beside this executable when installed side by side, else the build's.
    const QString sibling =
        QCoreApplication::applicationDirPath() + QStringLiteral("/driftlab-cli");
    return QFileInfo(sibling).isExecutable() ? sibling : QStringLiteral(DRIFTLAB_CLI);
}

int run(const QStringList& args) {
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
    const QCommandLineOption json{
        QStringLiteral("json"), QStringLiteral("Print the figures as one JSON object on stdout.")};
    const QCommandLineOption help{{QStringLiteral("h"), QStringLiteral("help")},
                                  QStringLiteral("Print this help on stdout.")};
    parser.setApplicationDescription(
        QStringLiteral("The performance figures of DriftLab on this machine, medians of "
                       "repetitions (docs/benchmarks.md)."));
    parser.addOptions({help, json, repeat, noPython, importMb, pushes, only, server});
    if (!parser.parse(args)) throw CliError(parser.errorText(), 2);
    if (parser.isSet(help)) {
        std::fputs(qPrintable(parser.helpText()), stdout);
        return 0;
    }
    if (!parser.positionalArguments().isEmpty())
        throw CliError(QStringLiteral("takes no arguments, got '%1'")
                           .arg(parser.positionalArguments().front()),
                       2);
    const int pushCount = parser.value(pushes).toInt();
    const int repetitions = std::max(1, parser.value(repeat).toInt());
    // The slow figures take three repetitions unless told: their data part takes tens of seconds.
    const int slowRepetitions = parser.isSet(repeat) ? repetitions : 3;
    const std::vector<SingleFigure> alone{
        {"push", [&] { return pushFigures(std::max(1, pushCount)); }, printPushLine},
        {"online", [&] { return onlineFigures(repetitions); }, printOnlineLine},
        {"logging", [&] { return loggingFigures(repetitions, parser.value(server)); },
         printLoggingLine},
        {"live-read", [] { return liveReadFigures(kLiveReadings); }, printLiveReadLine},
        {"plot", [&] { return plotFigures(std::max(3, repetitions)); }, printPlotLine},
        {"diagnosis", [&] { return diagnosisFigures(repetitions); },
         [](const QJsonObject& f) { printLine(diagnosisLine(f)); }},
        {"report", [&] { return reportFigures(slowRepetitions); }, printReportLine},
        // Six campaigns: three rounds of two at a time, so -j2 is not flattered by a lone last
        // item.
        {"batch", [&] { return batchFigures(6, repetitions); }, printBatchLine},
        {"model-choice", [&] { return modelChoiceFigures(slowRepetitions); }, printModelChoiceLine},
    };
    if (parser.isSet(only)) {
        const auto figure = std::find_if(alone.begin(), alone.end(), [&](const SingleFigure& f) {
            return parser.value(only) == QLatin1String(f.name);
        });
        if (figure == alone.end()) {
            QStringList names;
            for (const SingleFigure& f : alone) names << QLatin1String(f.name);
            throw CliError(QStringLiteral("--only: '%1' is not a figure it can measure alone (%2)")
                               .arg(parser.value(only), names.join(QStringLiteral(", "))),
                           2);
        }
        const QJsonObject figures = figure->measure();
        endProgressLine();
        if (parser.isSet(json))
            printJson(figures);
        else
            figure->print(figures);
        return 0;
    }
    // First, while no other child has raised this process's memory high-water marks.
    const int megabytes = parser.value(importMb).toInt();
    const QJsonObject import =
        megabytes > 0 ? importFigures(megabytes, std::min(repetitions, 3)) : QJsonObject();

    printProgress(QStringLiteral("simulation"), 0);
    const SimulationThroughput sim = measureSimulationThroughput(repetitions);
    printProgress(QStringLiteral("simulation"), 1);
    QJsonObject figures{{QStringLiteral("simulation_cell_steps_per_s"), sim.cell_steps_per_s},
                        {QStringLiteral("simulation_8h_campaign_ms"), sim.campaign_ms},
                        {QStringLiteral("online_step_us"), onlineStepMicroseconds()}};
    const QJsonObject push = pushCount > 0 ? pushFigures(pushCount) : QJsonObject();
    const QJsonObject liveRead = liveReadFigures(kLiveReadings);
    const QJsonObject plot = plotFigures(repetitions);
    for (const QJsonObject& part : {identificationFigures(std::min(repetitions, 3)),
                                    diagnosisFigures(std::min(repetitions, 3)), import,
                                    loggingFigures(std::min(repetitions, 3)), push, liveRead, plot})
        for (auto it = part.begin(); it != part.end(); ++it) figures[it.key()] = it.value();
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

    if (parser.isSet(json)) {
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

}  // namespace driftlab::bench

int main(int argc, char** argv) {
    // The plot figure draws the real dashboard, offscreen unless a screen is asked for.
    driftlab::cli::prepareHeadlessQt();
    QApplication app(argc, argv);
    FLAGS_minloglevel = google::GLOG_FATAL;  // Ceres's glog: only fatal messages
    QCoreApplication::setApplicationName(QStringLiteral("driftlab-bench"));
    try {
        return driftlab::bench::run(app.arguments());
    } catch (const driftlab::cli::CliError& e) {
        driftlab::cli::endProgressLine();
        std::fprintf(stderr, "driftlab-bench: %s\n", e.what());
        return e.exitCode;
    }
}
