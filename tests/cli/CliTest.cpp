// driftlab-cli import / export / info, run as a user runs them (a real process,
// a real SQLite file), and the guarantee that bad input changes nothing.
#include <gtest/gtest.h>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "core/bundle/BundleReader.h"
#include "tests/support/BadBundleCases.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

TEST(Cli, infoJsonDescribesRunsAndChannels) {
    CliResult r = runCli({QStringLiteral("info"), exampleBundlePath(), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    QJsonObject info = QJsonDocument::fromJson(r.out).object();
    EXPECT_EQ(info[QStringLiteral("name")].toString(),
              QStringLiteral("X axis moving-state example"));
    QJsonArray runs = info[QStringLiteral("runs")].toArray();
    ASSERT_EQ(runs.size(), 2);
    QJsonObject s1 = runs[0].toObject();
    EXPECT_EQ(s1[QStringLiteral("id")].toString(), QStringLiteral("S1"));
    EXPECT_EQ(s1[QStringLiteral("kind")].toString(), QStringLiteral("moving"));
    EXPECT_EQ(s1[QStringLiteral("positioning")].toInt(), 154);
    // 361 times x (6 temperatures + 3 axis columns) minus one dropout
    EXPECT_EQ(s1[QStringLiteral("samples")].toInt(), 361 * 9 - 1);
    QJsonArray channels = info[QStringLiteral("channels")].toArray();
    ASSERT_EQ(channels.size(), 13);
    EXPECT_EQ(channels[8].toObject()[QStringLiteral("role")].toString(), QStringLiteral("drift_x"));
    EXPECT_EQ(channels[8].toObject()[QStringLiteral("quantity")].toString(),
              QStringLiteral("displacement"));
}

TEST(Cli, importPrintsTheIdAndExportWritesTheSameCampaignBack) {
    QTemporaryDir dir;
    const QString dbPath = dir.filePath(QStringLiteral("lab.sqlite"));
    CliResult first =
        runCli({QStringLiteral("import"), exampleBundlePath(), QStringLiteral("--db"), dbPath});
    ASSERT_EQ(first.exitCode, 0) << first.err.constData();
    EXPECT_EQ(first.out.trimmed(), QByteArray("1"));
    // The same bundle again is noticed by its content; --again stores it once more.
    CliResult twice =
        runCli({QStringLiteral("import"), exampleBundlePath(), QStringLiteral("--db"), dbPath});
    EXPECT_EQ(twice.exitCode, 1);
    EXPECT_TRUE(reason(twice.err).contains("is already in " + dbPath.toUtf8() + " as campaign 1"))
        << twice.err.constData();
    CliResult second = runCli({QStringLiteral("import"), exampleBundlePath(),
                               QStringLiteral("--db"), dbPath, QStringLiteral("--again")});
    EXPECT_EQ(second.out.trimmed(), QByteArray("2")) << second.err.constData();

    const QString out = dir.filePath(QStringLiteral("exported"));
    CliResult exported =
        runCli({QStringLiteral("export"), QStringLiteral("--db"), dbPath,
                QStringLiteral("--campaign"), QStringLiteral("2"), QStringLiteral("--out"), out});
    ASSERT_EQ(exported.exitCode, 0) << exported.err.constData();
    bundle::BundleReadResult original = bundle::readBundle(exampleBundlePath());
    bundle::BundleReadResult back = bundle::readBundle(out);
    ASSERT_TRUE(back.ok()) << qPrintable(back.error->toString());
    EXPECT_EQ(*back.campaign, *original.campaign);

    CliResult info =
        runCli({QStringLiteral("info"), QStringLiteral("--db"), dbPath,
                QStringLiteral("--campaign"), QStringLiteral("1"), QStringLiteral("--json")});
    ASSERT_EQ(info.exitCode, 0) << info.err.constData();
    EXPECT_EQ(QJsonDocument::fromJson(info.out).object()[QStringLiteral("runs")].toArray().size(),
              2);
}

TEST(Cli, usageErrorsExitWithTwoAndSayWhy) {
    CliResult noCampaign =
        runCli({QStringLiteral("info"), QStringLiteral("--db"), QStringLiteral("/tmp/x.sqlite")});
    EXPECT_EQ(noCampaign.exitCode, 2);
    EXPECT_EQ(reason(noCampaign.err),
              QByteArray("driftlab-cli info: --db needs --campaign ID (a number)"));
    CliResult unknown = runCli({QStringLiteral("frobnicate")});
    EXPECT_EQ(unknown.exitCode, 2);
    CliResult missingCampaign =
        runCli({QStringLiteral("export"), QStringLiteral("--db"),
                QStringLiteral("/nonexistent/dir/x.sqlite"), QStringLiteral("--campaign"),
                QStringLiteral("1"), QStringLiteral("--out"), QStringLiteral("/tmp/never")});
    EXPECT_EQ(missingCampaign.exitCode, 1);
    EXPECT_TRUE(
        reason(missingCampaign.err).startsWith("driftlab-cli export: /nonexistent/dir/x.sqlite"))
        << missingCampaign.err.constData();
}

class CliBadBundle : public ::testing::TestWithParam<BadBundleCase> {};

TEST_P(CliBadBundle, importFailsWithOneLineAndLeavesTheDatabaseByteForByteUnchanged) {
    const BadBundleCase& bad = GetParam();
    QTemporaryDir dir;
    const QString dbPath = dir.filePath(QStringLiteral("lab.sqlite"));
    ASSERT_EQ(
        runCli({QStringLiteral("import"), exampleBundlePath(), QStringLiteral("--db"), dbPath})
            .exitCode,
        0);
    const QByteArray before = sha256OfFile(dbPath);

    const QString bundle = dir.filePath(QStringLiteral("bad"));
    copyBundle(exampleBundlePath(), bundle);
    bad.breakIt(bundle);
    CliResult r = runCli({QStringLiteral("import"), bundle, QStringLiteral("--db"), dbPath});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(r.out.isEmpty()) << r.out.constData();
    const QByteArray line = reason(r.err);
    RecordProperty("message", line.toStdString());  // the table of messages (--gtest_output=json)
    EXPECT_TRUE(
        line.startsWith("driftlab-cli import: " + bundle.toUtf8() + '/' + bad.expectedLocation))
        << line.constData();
    EXPECT_TRUE(line.contains(bad.expectedMessage)) << line.constData();
    EXPECT_EQ(sha256OfFile(dbPath), before) << "a rejected import must not touch the database";
}

INSTANTIATE_TEST_SUITE_P(EveryClass, CliBadBundle, ::testing::ValuesIn(badBundleCases()),
                         [](const auto& info) { return std::string(info.param.name); });
