// driftlab-bench as scripts use it: the figures' JSON keys (docs/benchmarks.md),
// its help, and that the product's executable no longer carries it.
#include <gtest/gtest.h>

#include "tests/support/CliRunner.h"

using namespace driftlab::test;

TEST(BenchCli, jsonCarriesTheFiguresScriptsRelyOn) {
    CliResult r = runProgram(
        QStringLiteral(DRIFTLAB_BENCH),
        {QStringLiteral("--json"), QStringLiteral("--repeat"), QStringLiteral("1"),
         QStringLiteral("--no-python"), QStringLiteral("--import-mb"), QStringLiteral("4")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject figures = json(r);
    // Figures, not verdicts: speed is judged by reading them, never by a test.
    for (const char* key : {"simulation_cell_steps_per_s", "identification_s", "online_step_us",
                            "diagnosis_s", "import_samples_per_s", "import_peak_rss_mb"})
        EXPECT_GT(figures[QLatin1String(key)].toDouble(), 0) << key;
    // The import figure really imported the file it wrote: 4 MB of 11-column rows.
    EXPECT_GT(figures[QStringLiteral("import_samples")].toDouble(), 300'000);
    EXPECT_GE(figures[QStringLiteral("import_csv_mb")].toDouble(), 4.0);
    EXPECT_GT(figures[QStringLiteral("identification_iterations")].toInt(), 0);
    EXPECT_FALSE(figures.contains(QStringLiteral("scipy_cell_steps_per_s")));
}

TEST(BenchCli, helpAndRefusalsFollowTheCliConventions) {
    const CliResult help = runProgram(QStringLiteral(DRIFTLAB_BENCH), {QStringLiteral("--help")});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_TRUE(help.out.contains("--only")) << help.out.constData();
    const CliResult unknown = runProgram(QStringLiteral(DRIFTLAB_BENCH),
                                         {QStringLiteral("--only"), QStringLiteral("nap")});
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_TRUE(reason(unknown.err).startsWith("driftlab-bench: --only: 'nap' is not a figure"))
        << unknown.err.constData();
    // The product has no bench command: it is not a benchmark harness.
    const CliResult cli = runCli({QStringLiteral("bench")});
    EXPECT_EQ(cli.exitCode, 2);
    EXPECT_TRUE(reason(cli.err).contains("unknown command 'bench'")) << cli.err.constData();
}
