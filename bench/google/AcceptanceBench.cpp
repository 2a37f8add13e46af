// The acceptance of the example bundle's positioning run (readings at 20 °C,
// environment, uncertainty budget, verdicts) against the ISO 230-2
// evaluation alone and the comparison of every standard on the same
// readings: what --spec and --standard all add to iso230-2.
#include <benchmark/benchmark.h>

#include "core/bundle/BundleReader.h"
#include "core/iso/PositioningAcceptance.h"
#include "core/iso/PositioningStandards.h"

namespace {

using namespace driftlab;

const Campaign& example() {
    static const Campaign campaign =
        *bundle::readBundle(
             QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/examples/x-axis-moving-state"))
             .campaign;
    return campaign;
}

iso::AcceptanceSpecification specification() {
    QString error;
    return *iso::readAcceptanceSpecification(
        QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/examples/x-axis-acceptance.json"), &error);
}

void BM_Iso230_2Evaluation(benchmark::State& state) {
    const auto readings = iso::readingsOf(*example().findRun(QStringLiteral("S1")));
    for (auto _ : state) benchmark::DoNotOptimize(iso::evaluate(readings));
}
BENCHMARK(BM_Iso230_2Evaluation)->Unit(benchmark::kMicrosecond);

void BM_AcceptanceOfExampleRun(benchmark::State& state) {
    const Campaign& campaign = example();
    const Run& run = *campaign.findRun(QStringLiteral("S1"));
    const iso::AcceptanceSpecification spec = specification();
    for (auto _ : state) benchmark::DoNotOptimize(iso::evaluateAcceptance(campaign, run, spec));
}
BENCHMARK(BM_AcceptanceOfExampleRun)->Unit(benchmark::kMicrosecond);

void BM_StandardsComparison(benchmark::State& state) {
    const auto readings = iso::readingsOf(*example().findRun(QStringLiteral("S1")));
    for (auto _ : state) benchmark::DoNotOptimize(iso::compareStandards(readings, {}));
}
BENCHMARK(BM_StandardsComparison)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
