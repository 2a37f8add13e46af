// The compensation push of a 256-point table to the simulated controller on
// 127.0.0.1 (real Modbus TCP through libmodbus on both sides): one push per
// iteration, connect to read-back. `driftlab-bench --only push` reports
// the median and worst of 50.
#include <benchmark/benchmark.h>

#include <cmath>

#include "acquisition/push/TablePush.h"
#include "acquisition/sim/SimulatedController.h"

using namespace driftlab;

static void BM_Push256PointTable(benchmark::State& state) {
    sim::SimulatedController controller;
    QString error;
    if (!controller.start(&error)) {
        state.SkipWithError(qPrintable(error));
        return;
    }
    compensation::CompensationTable tables[2];
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 256; ++i) {
            tables[k].position_mm.push_back(i * 2.5);
            tables[k].correction_plus_um.push_back((k ? 6 : 8) * std::sin(0.05 * i));
            tables[k].correction_minus_um.push_back(tables[k].correction_plus_um.back());
        }
    const modbus::ModbusUrl url{QStringLiteral("127.0.0.1"), controller.port(), 1};
    int n = 0;
    for (auto _ : state) {
        const push::PushResult result = push::pushTable(url, tables[n++ % 2]);
        if (!result.ok()) state.SkipWithError(qPrintable(result.message));
    }
}
BENCHMARK(BM_Push256PointTable)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
