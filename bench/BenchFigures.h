#pragma once
// The figures driftlab-bench measures, one function per figure family (each in
// its own file), and the line each prints without --json. Every figure is a
// median of repetitions on this machine; docs/benchmarks.md lists the keys.

#include <QJsonObject>
#include <QString>

#include "app/cli/ConsoleOutput.h"
#include "core/domain/Median.h"

namespace driftlab::bench {

using cli::CliError;
using cli::endProgressLine;
using cli::printJson;
using cli::printLine;
using cli::printProgress;

/// Channels of the live read path and the dashboard figures: a 64-channel module.
constexpr int kLiveChannels = 64;

/// The driftlab-cli the import and batch figures run, as a user runs it.
QString cliExecutable();

/// CoreFigures.cpp: heat-transfer identification on the five-run rig campaign.
QJsonObject identificationFigures(int repetitions);
/// CoreFigures.cpp: the diagnosis against one identification of the same campaign.
QJsonObject diagnosisFigures(int repetitions);
QString diagnosisLine(const QJsonObject& figures);
/// CoreFigures.cpp: one live-model step with a 128-point table update, µs.
double onlineStepMicroseconds();
/// CoreFigures.cpp: the same simulation in NumPy/SciPy, when Python has SciPy.
QJsonObject scipyFigures();
/// ImportThroughput.cpp: `import` of a samples.csv of `megabytes` MB in a child process.
QJsonObject importFigures(int megabytes, int repetitions);
/// PushThroughput.cpp: `pushes` pushes of a 256-point table to the simulated controller.
QJsonObject pushFigures(int pushes);
void printPushLine(const QJsonObject& figures);
/// LoggingThroughput.cpp; with `serverUrl`, also the upload rate into that server store.
QJsonObject loggingFigures(int repetitions, const QString& serverUrl = {});
void printLoggingLine(const QJsonObject& figures);
/// LiveReadLatency.cpp: device reading → reader of the live read path, µs.
QJsonObject liveReadFigures(int readings);
void printLiveReadLine(const QJsonObject& figures);
/// PlotRedraw.cpp: the live dashboard's redraw and the GUI thread's stalls, ms.
QJsonObject plotFigures(int repetitions);
void printPlotLine(const QJsonObject& figures);
/// ReportDrawing.cpp: the acceptance report's data and PDF drawing, ms.
QJsonObject reportFigures(int repetitions);
void printReportLine(const QJsonObject& figures);
/// ModelChoice.cpp: `fit --model auto` and `arx` on spindle runs' drift, ms.
QJsonObject modelChoiceFigures(int repetitions);
void printModelChoiceLine(const QJsonObject& figures);
/// BatchThroughput.cpp: `batch` of `campaigns` simulated campaigns, -j1 and -j2.
QJsonObject batchFigures(int campaigns, int repetitions);
void printBatchLine(const QJsonObject& figures);

}  // namespace driftlab::bench
