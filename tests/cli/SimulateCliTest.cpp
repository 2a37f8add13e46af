// driftlab-cli simulate: a campaign bundle from the simulated rig, its plots,
// and a one-line reason for every bad request.
#include <gtest/gtest.h>

#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/support/CliRunner.h"

using namespace driftlab::test;

TEST(SimulateCli, writesABundleThatInfoReadsAndPlotsOfTheTrueScrewState) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("campaign"));
    const QString plots = dir.filePath(QStringLiteral("plots"));
    CliResult sim =
        runCli({QStringLiteral("simulate"), QStringLiteral("--out"), bundle,
                QStringLiteral("--seed"), QStringLiteral("7"), QStringLiteral("--plots"), plots,
                QStringLiteral("--spindle"), QStringLiteral("--json")});
    ASSERT_EQ(sim.exitCode, 0) << sim.err.constData();
    const QJsonObject out = QJsonDocument::fromJson(sim.out).object();
    EXPECT_EQ(out[QStringLiteral("runs")].toArray().size(), 6);
    for (const auto& png : out[QStringLiteral("plots")].toArray()) {
        const QImage image(png.toString());
        EXPECT_EQ(image.width(), 960) << qPrintable(png.toString());
        EXPECT_EQ(image.height(), 600);
    }
    EXPECT_EQ(out[QStringLiteral("plots")].toArray().size(), 2);

    CliResult info = runCli({QStringLiteral("info"), bundle, QStringLiteral("--json")});
    ASSERT_EQ(info.exitCode, 0) << info.err.constData();
    const QJsonArray runs =
        QJsonDocument::fromJson(info.out).object()[QStringLiteral("runs")].toArray();
    ASSERT_EQ(runs.size(), 6);
    QStringList ids;
    for (const auto& r : runs) {
        ids << r.toObject()[QStringLiteral("id")].toString();
        if (r.toObject()[QStringLiteral("kind")].toString() == QLatin1String("moving")) {
            EXPECT_EQ(r.toObject()[QStringLiteral("positioning")].toInt(), 18 * 22);
        }
    }
    EXPECT_EQ(ids, QStringList({"S1", "S2", "S3", "S4", "S5", "SP1"}));
}

TEST(SimulateCli, effectsAndRunsAreChosenOnTheCommandLine) {
    QTemporaryDir dir;
    CliResult sim = runCli({QStringLiteral("simulate"), QStringLiteral("--out"), dir.path(),
                            QStringLiteral("--runs"), QStringLiteral("S4,S5"),
                            QStringLiteral("--effect"), QStringLiteral("sensor_lag:T_nut=300"),
                            QStringLiteral("--effect"), QStringLiteral("frame_growth=2")});
    ASSERT_EQ(sim.exitCode, 0) << sim.err.constData();
    CliResult info = runCli({QStringLiteral("info"), dir.path(), QStringLiteral("--json")});
    const QJsonArray runs =
        QJsonDocument::fromJson(info.out).object()[QStringLiteral("runs")].toArray();
    ASSERT_EQ(runs.size(), 2);
    EXPECT_EQ(runs[0].toObject()[QStringLiteral("id")].toString(), QStringLiteral("S4"));
}

TEST(SimulateCli, badRequestsExitNonZeroWithTheReason) {
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("never"));
    auto simulate = [&](QStringList extra) {
        return runCli(QStringList{QStringLiteral("simulate"), QStringLiteral("--out"), out} +
                      extra);
    };
    CliResult unknown = simulate({QStringLiteral("--effect"), QStringLiteral("gremlins=1")});
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_TRUE(reason(unknown.err).contains("unknown effect id 'gremlins'"))
        << unknown.err.constData();
    CliResult noChannel =
        simulate({QStringLiteral("--effect"), QStringLiteral("sensor_lag:T_x=10")});
    EXPECT_EQ(noChannel.exitCode, 1);
    EXPECT_TRUE(reason(noChannel.err).contains("no temperature channel 'T_x'"))
        << noChannel.err.constData();
    CliResult badRun = simulate({QStringLiteral("--runs"), QStringLiteral("S9")});
    EXPECT_EQ(badRun.exitCode, 2);
    EXPECT_TRUE(reason(badRun.err).contains("no moving state 'S9'"));
    CliResult noOut = runCli({QStringLiteral("simulate")});
    EXPECT_EQ(noOut.exitCode, 2);
    EXPECT_FALSE(QFileInfo::exists(out));
}
