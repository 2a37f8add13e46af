// bench --only batch: batch throughput in campaigns per minute, one at a time
// (-j1) against two at a time (-j2), on simulated five-state campaigns with
// info, fit and diagnose (docs/batch.md). Each figure is the median wall time
// of `repetitions` whole `driftlab-cli batch` runs, children included.
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <algorithm>
#include <cstdio>
#include <vector>

#include "bench/BenchFigures.h"

namespace driftlab::bench {
namespace {

/// Runs this executable with `args`; throws CliError with its last stderr
/// line unless it exits with `expected`.
void runSelf(const QStringList& args, int expected = 0) {
    QProcess p;
    p.start(cliExecutable(), args);
    if (!p.waitForFinished(-1) || p.exitStatus() != QProcess::NormalExit ||
        p.exitCode() != expected)
        throw CliError(QStringLiteral("batch bench: driftlab-cli %1: %2")
                           .arg(args.value(0), QString::fromUtf8(p.readAllStandardError().trimmed())
                                                   .split(QLatin1Char('\n'))
                                                   .constLast()));
}

}  // namespace

QJsonObject batchFigures(int campaigns, int repetitions) {
    QTemporaryDir dir;
    if (!dir.isValid()) throw CliError(QStringLiteral("batch bench: no temporary folder"));
    for (int i = 0; i < campaigns; ++i) {
        runSelf({QStringLiteral("simulate"), QStringLiteral("--out"),
                 dir.filePath(QStringLiteral("campaign-%1").arg(i)), QStringLiteral("--seed"),
                 QString::number(i + 1)});
        printProgress(QStringLiteral("batch: simulating"), (i + 1.0) / campaigns);
    }
    QJsonObject figures{{QStringLiteral("batch_campaigns"), campaigns},
                        {QStringLiteral("batch_what"), QStringLiteral("info,fit,diagnose")}};
    for (int jobs : {1, 2}) {
        std::vector<double> minutes;
        for (int k = 0; k < repetitions; ++k) {
            QElapsedTimer timer;
            timer.start();
            runSelf({QStringLiteral("batch"), dir.path(), QStringLiteral("-j"),
                     QString::number(jobs), QStringLiteral("--what"),
                     QStringLiteral("info,fit,diagnose")});
            minutes.push_back(timer.nsecsElapsed() * 1e-9 / 60);
            printProgress(QStringLiteral("batch -j%1").arg(jobs), (k + 1.0) / repetitions);
        }
        figures[QStringLiteral("batch_j%1_campaigns_per_min").arg(jobs)] =
            campaigns / median(minutes);
    }
    return figures;
}

void printBatchLine(const QJsonObject& figures) {
    const double one = figures[QStringLiteral("batch_j1_campaigns_per_min")].toDouble();
    const double two = figures[QStringLiteral("batch_j2_campaigns_per_min")].toDouble();
    printLine(QStringLiteral("batch           %1 campaigns/min with -j1, %2 with -j2 (×%3; %4 "
                             "five-state campaigns, info,fit,diagnose, medians)")
                  .arg(one, 0, 'f', 2)
                  .arg(two, 0, 'f', 2)
                  .arg(two / one, 0, 'f', 2)
                  .arg(figures[QStringLiteral("batch_campaigns")].toInt()));
}

}  // namespace driftlab::bench
