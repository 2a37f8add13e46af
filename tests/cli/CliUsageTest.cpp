// driftlab-cli's command line as scripts and people rely on it: --version,
// help on stdout, usage errors on stderr with the reason on the last line,
// distinct exit codes, and no score called held-out that is not.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>

#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab::test;

namespace {

const QStringList kBuilt{"import",         "export",   "info",     "simulate",   "fit",
                         "compare",        "diagnose", "iso230-2", "compensate", "pushes",
                         "controller-sim", "live",     "iso230-3", "health",     "run",
                         "report",         "batch",    "sync"};

/// The usage a refused command line shows on stderr before its reason.
QByteArray usage() {
    return runCli({QStringLiteral("--help")}).out;
}

}  // namespace

TEST(CliUsage, versionPrintsOnStdoutAndExitsZero) {
    CliResult r = runCli({QStringLiteral("--version")});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, QByteArray("driftlab-cli " DRIFTLAB_VERSION "\n"));
    EXPECT_EQ(r.err, QByteArray());
}

TEST(CliUsage, helpPrintsTheCommandsAndExitCodesOnStdout) {
    const QByteArray help = usage();
    ASSERT_TRUE(help.startsWith("Usage: driftlab-cli COMMAND [options]\n")) << help.constData();
    for (const QString& name : kBuilt)
        EXPECT_TRUE(help.contains("\n  " + name.toUtf8() + ' ')) << qPrintable(name);
    EXPECT_TRUE(
        help.contains("Exit codes: 0 done, 1 failed (last stderr line says why), 2 usage "
                      "error,\n            3 run aborted with Ctrl-C (the run is kept, "
                      "interrupted).\n"));
    for (const char* spelling : {"--help", "-h", "help"}) {
        CliResult r = runCli({QLatin1String(spelling)});
        EXPECT_EQ(r.exitCode, 0) << spelling;
        EXPECT_EQ(r.out, help) << spelling;
        EXPECT_EQ(r.err, QByteArray()) << spelling;
    }
}

TEST(CliUsage, usageListsEveryCommandAsBuilt) {
    // report and batch were the last commands listed as not built yet (issue 14).
    const QList<QByteArray> lines = usage().split('\n');
    for (const QString& name : kBuilt) {
        const auto at = std::find_if(lines.begin(), lines.end(), [&](const QByteArray& line) {
            return line.startsWith("  " + name.toUtf8() + ' ');
        });
        ASSERT_NE(at, lines.end()) << qPrintable(name);
        EXPECT_FALSE(at->endsWith("   (not built yet)")) << at->constData();
    }
    EXPECT_FALSE(usage().contains("(not built yet)"));
    EXPECT_FALSE(usage().contains("\n  batch-item")) << "the batch child command is hidden";
}

TEST(CliUsage, bareCommandLineAsksForACommandOnStderr) {
    CliResult r = runCli({});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, QByteArray());
    EXPECT_EQ(r.err, usage() + "\ndriftlab-cli: a command is needed\n");
}

TEST(CliUsage, misspelledCommandNamedOnLastStderrLine) {
    CliResult r = runCli({QStringLiteral("imprt"), QStringLiteral("bundle")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, QByteArray());
    EXPECT_EQ(r.err,
              usage() + "\ndriftlab-cli: unknown command 'imprt' (did you mean 'import'?)\n");
}

TEST(CliUsage, shortenedCommandSuggestsTheOneItStartsWith) {
    CliResult r = runCli({QStringLiteral("diag")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(reason(r.err), "driftlab-cli: unknown command 'diag' (did you mean 'diagnose'?)");
}

TEST(CliUsage, unknownCommandWithNothingCloseIsNamedWithoutAGuess) {
    CliResult r = runCli({QStringLiteral("frobnicate")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, QByteArray());
    EXPECT_EQ(r.err, usage() + "\ndriftlab-cli: unknown command 'frobnicate'\n");
}

TEST(CliUsage, optionBeforeTheCommandIsNamed) {
    CliResult r = runCli({QStringLiteral("--json"), QStringLiteral("info")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(reason(r.err),
              "driftlab-cli: unknown option '--json' (a COMMAND comes first, its options after "
              "it)");
}

TEST(CliUsage, helpCommandPrintsCommandHelpOnStdout) {
    CliResult r = runCli({QStringLiteral("help"), QStringLiteral("import")});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.err, QByteArray());
    EXPECT_EQ(
        r.out,
        QByteArray("Usage: driftlab-cli import [options] BUNDLE\n"
                   "Store a campaign bundle in the database (one transaction); prints the "
                   "campaign id.\n"
                   "Required: BUNDLE, --db FILE\n"
                   "\n"
                   "Options:\n"
                   "  -h, --help   Print this help on stdout.\n"
                   "  --json       Print the result as JSON on stdout.\n"
                   "  --db <FILE>  Campaign store: a SQLite file, or\n"
                   "               postgresql://USER@HOST[:PORT]/DB for a store on a PostgreSQL\n"
                   "               server. (required)\n"
                   "  --again      Import a bundle whose content the store already holds "
                   "once more.\n"
                   "\n"
                   "Arguments:\n"
                   "  BUNDLE       Campaign bundle: a folder or a .zip of one (campaign.json,\n"
                   "               samples.csv, ...).\n"));
}

TEST(CliUsage, helpCommandIsTheCommandsOwnHelp) {
    for (const QString& name : kBuilt) {
        CliResult viaHelp = runCli({QStringLiteral("help"), name});
        CliResult own = runCli({name, QStringLiteral("--help")});
        EXPECT_EQ(viaHelp.exitCode, 0) << qPrintable(name);
        EXPECT_EQ(own.exitCode, 0) << qPrintable(name);
        EXPECT_EQ(viaHelp.out, own.out) << qPrintable(name);
        EXPECT_EQ(own.err, QByteArray()) << qPrintable(name);
        EXPECT_TRUE(own.out.startsWith("Usage: driftlab-cli " + name.toUtf8() + " [options]"))
            << own.out.constData();
    }
}

TEST(CliUsage, commandHelpSaysWhichOptionsAreRequired) {
    const QByteArray fit = runCli({QStringLiteral("fit"), QStringLiteral("--help")}).out;
    EXPECT_TRUE(fit.startsWith("Usage: driftlab-cli fit [options] BUNDLE\n")) << fit.constData();
    EXPECT_TRUE(fit.contains("\nRequired: BUNDLE (or --db FILE --campaign ID), --model NAME\n"))
        << fit.constData();
    const QByteArray exp = runCli({QStringLiteral("export"), QStringLiteral("--help")}).out;
    EXPECT_TRUE(exp.startsWith("Usage: driftlab-cli export [options]\n")) << exp.constData();
    EXPECT_TRUE(exp.contains("\nRequired: --db FILE, --campaign ID, --out DIR\n"))
        << exp.constData();
}

TEST(CliUsage, missingRequiredOptionNamesCommandAndOption) {
    CliResult import = runCli({QStringLiteral("import"), exampleBundlePath()});
    EXPECT_EQ(import.exitCode, 2);
    EXPECT_EQ(import.out, QByteArray());
    EXPECT_EQ(import.err, "driftlab-cli import: --db FILE is required\n");
    CliResult exported =
        runCli({QStringLiteral("export"), QStringLiteral("--db"), QStringLiteral("x.sqlite"),
                QStringLiteral("--campaign"), QStringLiteral("1")});
    EXPECT_EQ(exported.exitCode, 2);
    EXPECT_EQ(exported.err, "driftlab-cli export: --out DIR is required\n");
    CliResult fit = runCli({QStringLiteral("fit"), exampleBundlePath()});
    EXPECT_EQ(fit.exitCode, 2);
    EXPECT_EQ(fit.err, "driftlab-cli fit: --model NAME is required\n");
}

TEST(CliUsage, badOptionValueNamesCommandAndOption) {
    CliResult r = runCli({QStringLiteral("simulate"), QStringLiteral("--out"),
                          QStringLiteral("/nonexistent/never"), QStringLiteral("--seed"),
                          QStringLiteral("minus")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, QByteArray());
    EXPECT_EQ(r.err, "driftlab-cli simulate: --seed: not a non-negative integer\n");
    CliResult unknown = runCli({QStringLiteral("info"), QStringLiteral("--frob")});
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_EQ(unknown.err, "driftlab-cli info: Unknown option 'frob'.\n");
}

TEST(CliUsage, fitRefusesTestRunThatIsAlsoTraining) {
    CliResult r = runCli({QStringLiteral("fit"), exampleBundlePath(), QStringLiteral("--model"),
                          QStringLiteral("mlr"), QStringLiteral("--train"), QStringLiteral("S1"),
                          QStringLiteral("--test"), QStringLiteral("S1")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, QByteArray());
    EXPECT_EQ(r.err,
              "driftlab-cli fit: run S1 is both a training and a test run: a held-out score "
              "needs runs the model has not seen\n");
}

TEST(CliUsage, fitRefusesEveryRunThatIsBothAndNamesThemAll) {
    CliResult r =
        runCli({QStringLiteral("fit"), exampleBundlePath(), QStringLiteral("--model"),
                QStringLiteral("mlr"), QStringLiteral("--train"), QStringLiteral("S1,S2,S3"),
                QStringLiteral("--test"), QStringLiteral("S3,S1")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err,
              "driftlab-cli fit: runs S1, S3 are both training and test runs: a held-out score "
              "needs runs the model has not seen\n");
}

// The example campaign has one feed-axis run: the default split leaves no
// test run, and what is left is a training score.
TEST(CliUsage, fitOnAOneRunCampaignLabelsATrainingScore) {
    CliResult r = runCli({QStringLiteral("fit"), exampleBundlePath(), QStringLiteral("--model"),
                          QStringLiteral("mlr"), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject fit = json(r);
    EXPECT_EQ(fit[QStringLiteral("score_kind")].toString(), QStringLiteral("training"));
    EXPECT_EQ(fit[QStringLiteral("train_runs")].toArray(), QJsonArray({"S1"}));
    EXPECT_EQ(fit[QStringLiteral("test_runs")].toArray(), QJsonArray());
    EXPECT_EQ(fit[QStringLiteral("test")].toObject(), QJsonObject()) << "no held-out figures";
    const QJsonObject score = fit[QStringLiteral("score")].toObject();
    EXPECT_EQ(score[QStringLiteral("runs")].toArray(), QJsonArray({"S1"}));
    EXPECT_GT(score[QStringLiteral("rms_um")].toDouble(), 0);
}

TEST(CliUsage, fitWithAnEmptyTestListPrintsATrainingScore) {
    CliResult r = runCli({QStringLiteral("fit"), exampleBundlePath(), QStringLiteral("--model"),
                          QStringLiteral("mlr"), QStringLiteral("--train"), QStringLiteral("S1"),
                          QStringLiteral("--test"), QString()});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QByteArray last = r.out.trimmed().split('\n').last();
    EXPECT_TRUE(
        last.startsWith("training score on S1 (the runs it was fitted on; no run held out, "
                        "so not a held-out score): RMS "))
        << r.out.constData();
    EXPECT_FALSE(r.out.contains("held-out score on")) << r.out.constData();
}

TEST(CliUsage, compareLabelsTheDiagonalAsATrainingScore) {
    CliResult r =
        runCli({QStringLiteral("compare"), exampleBundlePath(), QStringLiteral("--models"),
                QStringLiteral("mlr"), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_EQ(json(r)[QStringLiteral("diagonal")].toString(),
              QStringLiteral("training score (fitted and scored on the same run)"));
    CliResult text = runCli({QStringLiteral("compare"), exampleBundlePath(),
                             QStringLiteral("--models"), QStringLiteral("mlr")});
    ASSERT_EQ(text.exitCode, 0) << text.err.constData();
    const QList<QByteArray> lines = text.out.split('\n');
    ASSERT_GE(lines.size(), 6) << text.out.constData();
    EXPECT_EQ(lines[1],
              "(…) on the diagonal: training score (fitted and scored on the same run); off it: "
              "held-out scores");
    EXPECT_TRUE(lines[5].startsWith("S1 ")) << text.out.constData();
    EXPECT_TRUE(lines[5].trimmed().endsWith(")")) << "the S1/S1 cell is in brackets";
}

TEST(CliUsage, diagnoseRefusesTestRunThatIsAlsoTraining) {
    CliResult r =
        runCli({QStringLiteral("diagnose"), exampleBundlePath(), QStringLiteral("--train"),
                QStringLiteral("S1,S2"), QStringLiteral("--test"), QStringLiteral("S2")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, QByteArray());
    EXPECT_EQ(r.err,
              "driftlab-cli diagnose: run S2 is both a training and a test run: a held-out score "
              "needs runs the model has not seen\n");
}
