// Identification of the heat-transfer model on the five-run rig campaign
// (docs/benchmarks.md: < 2 s): wall time, Ceres iterations, final cost.
#include <benchmark/benchmark.h>

#include "core/models/HeatTransferModel.h"
#include "core/rig/CampaignSimulator.h"

using namespace driftlab;

static void BM_HeatTransferIdentificationFiveRuns(benchmark::State& state) {
    const Campaign campaign = rig::simulateCampaign(rig::RigSpec{});
    const models::DatasetResult data =
        models::buildDataset(campaign, {"S1", "S2", "S3", "S4", "S5"});
    if (!data.ok()) {
        state.SkipWithError(qPrintable(data.error));
        return;
    }
    models::FitSummary fit;
    for (auto _ : state) {
        models::HeatTransferModel model;
        fit = model.fit(data.runs);
        if (!fit.success) state.SkipWithError(qPrintable(fit.message));
    }
    state.counters["iterations"] = fit.iterations;
    state.counters["final_cost"] = fit.metrics[QStringLiteral("final_cost")];
    state.counters["observations"] = double(fit.observations);
}
BENCHMARK(BM_HeatTransferIdentificationFiveRuns)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
