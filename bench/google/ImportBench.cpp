// Import throughput: a one-million-sample bundle checked, then streamed from
// disk into one SQLite transaction (what `driftlab-cli import` does).
#include <benchmark/benchmark.h>
#include <QTemporaryDir>

#include "core/bundle/BundleReader.h"
#include "core/bundle/BundleWriter.h"
#include "db/CampaignImport.h"
#include "db/CampaignStore.h"
#include "tests/support/BundleTestSupport.h"

using namespace driftlab;

static void BM_ImportMillionSampleBundle(benchmark::State& state) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("bundle"));
    bundle::writeBundle(test::generatedCampaign(125'000), bundle);  // 8 columns -> 1e6 samples
    int round = 0;
    for (auto _ : state) {
        QString error;
        const auto source = bundle::openBundleFolder(bundle, &error);
        const db::BundleCheck checked = db::checkBundle(*source);
        auto store =
            db::CampaignStore::open(dir.filePath(QStringLiteral("lab%1.sqlite").arg(round++)),
                                    db::StoreAccess::CreateIfMissing, &error);
        if (!checked.ok() || !store || !db::importBundle(*store, *source, checked).campaignId ||
            !store->publish(&error))
            state.SkipWithError("import failed");
    }
    state.counters["samples_per_s"] =
        benchmark::Counter(1e6 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ImportMillionSampleBundle)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_ReadMillionSampleBundle(benchmark::State& state) {
    QTemporaryDir dir;
    bundle::writeBundle(test::generatedCampaign(125'000), dir.path());
    for (auto _ : state) benchmark::DoNotOptimize(bundle::readBundle(dir.path()));
    state.counters["samples_per_s"] =
        benchmark::Counter(1e6 * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ReadMillionSampleBundle)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
