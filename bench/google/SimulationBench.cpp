// Screw simulation throughput: one 1 s step of a 200-cell screw with the nut
// stroking through it, and a whole 8-hour moving-state campaign at 1 s steps
// (the figure driftlab-bench reports, from the same BenchmarkCampaign).
#include <benchmark/benchmark.h>

#include <vector>

#include "bench/SimulationThroughput.h"
#include "core/physics/ScrewThermalModel.h"

using namespace driftlab;
using namespace driftlab::physics;
using namespace driftlab::bench;

static void BM_ScrewStep200CellsWithNutStroke(benchmark::State& state) {
    const BenchmarkCampaign campaign;
    // The first 600 s of the campaign are reciprocation only: every step holds
    // half a stroke of the nut (2.1 s strokes, 1 s steps).
    const double span_s = 600;
    std::vector<MotionSegment> motion;
    for (const MotionSegment& s : campaign.motion)
        if (s.end_s <= span_s) motion.push_back(s);
    StepConditions c;
    c.dt_s = 1;
    c.ambient_begin_C = c.ambient_end_C = 20;
    c.motion = motion;
    ScrewThermalModel model(campaign.parameters, 20);
    for (auto _ : state) {
        if (model.time_s() + c.dt_s > span_s) {
            state.PauseTiming();  // once per 600 steps
            model = ScrewThermalModel(campaign.parameters, 20);
            state.ResumeTiming();
        }
        model.step(c);
        benchmark::DoNotOptimize(model.temperatures_C().data());
    }
    // items/s = cell-steps per second
    state.SetItemsProcessed(state.iterations() * BenchmarkCampaign::kCells);
}
BENCHMARK(BM_ScrewStep200CellsWithNutStroke);

static void BM_EightHourCampaign200Cells(benchmark::State& state) {
    const BenchmarkCampaign campaign;
    for (auto _ : state) benchmark::DoNotOptimize(campaign.run());
    state.counters["cell_steps_per_s"] = benchmark::Counter(
        campaign.cellSteps() * double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["steps"] = double(campaign.steps());
}
BENCHMARK(BM_EightHourCampaign200Cells)->Unit(benchmark::kMillisecond)->UseRealTime();

// The library entry point the CLI calls, timed by itself (median of 3 campaigns).
static void BM_MeasureSimulationThroughput(benchmark::State& state) {
    SimulationThroughput result;
    for (auto _ : state) result = measureSimulationThroughput(3);
    state.counters["median_cell_steps_per_s"] = result.cell_steps_per_s;
    state.counters["median_campaign_ms"] = result.campaign_ms;
}
BENCHMARK(BM_MeasureSimulationThroughput)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
