// bench: the compensation push of a 256-point table to the simulated
// controller on 127.0.0.1 over real Modbus TCP, median and worst of many
// pushes (each one connects, stages, commits, waits and reads back).
#include <QElapsedTimer>
#include <algorithm>
#include <cmath>

#include "acquisition/push/TablePush.h"
#include "acquisition/sim/SimulatedController.h"
#include "bench/BenchFigures.h"

namespace driftlab::bench {

QJsonObject pushFigures(int pushes) {
    sim::SimulatedController controller;
    QString error;
    if (!controller.start(&error)) throw CliError(QStringLiteral("push bench: ") + error);
    // Two tables in turn, so that every push really changes the active table.
    compensation::CompensationTable tables[2];
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 256; ++i) {
            const double value = (k ? 6 : 8) * std::sin(0.05 * i);
            tables[k].position_mm.push_back(i * 2.5);
            tables[k].correction_plus_um.push_back(value);
            tables[k].correction_minus_um.push_back(value);
        }
    const modbus::ModbusUrl url{QStringLiteral("127.0.0.1"), controller.port(), 1};
    std::vector<double> ms;
    for (int n = 0; n < pushes; ++n) {
        QElapsedTimer timer;
        timer.start();
        const push::PushResult result = push::pushTable(url, tables[n % 2]);
        ms.push_back(timer.nsecsElapsed() * 1e-6);
        if (!result.ok()) throw CliError(QStringLiteral("push bench: ") + result.message);
        printProgress(QStringLiteral("push"), (n + 1.0) / pushes);
    }
    return {{QStringLiteral("push_256_median_ms"), median(ms)},
            {QStringLiteral("push_256_worst_ms"), *std::max_element(ms.begin(), ms.end())},
            {QStringLiteral("push_256_count"), pushes}};
}

void printPushLine(const QJsonObject& push) {
    printLine(QStringLiteral("push            256-point table to the simulated controller over "
                             "Modbus TCP, %1 pushes: median %2 ms, worst %3 ms")
                  .arg(push[QStringLiteral("push_256_count")].toInt())
                  .arg(push[QStringLiteral("push_256_median_ms")].toDouble(), 0, 'f', 2)
                  .arg(push[QStringLiteral("push_256_worst_ms")].toDouble(), 0, 'f', 2));
}

}  // namespace driftlab::bench
