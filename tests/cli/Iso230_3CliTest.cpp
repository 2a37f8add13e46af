// driftlab-cli iso230-3 as scripts use it: JSON for the example bundle's
// moving run S1 and spindle run SP1 (the numbers behind the golden tests are
// in tests/iso/Iso230_3Test.cpp), the same from the database, the text
// table, and usage errors that exit 2.

#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab::test;

namespace {

CliResult iso3(QStringList args) {
    return runCli(QStringList{QStringLiteral("iso230-3")} + args);
}

QJsonObject runOf(const QJsonObject& o, const QString& id) {
    for (const QJsonValue& run : o.value(QStringLiteral("runs")).toArray())
        if (run[QStringLiteral("run")].toString() == id) return run.toObject();
    ADD_FAILURE() << "no run " << qPrintable(id);
    return {};
}

}  // namespace

TEST(Iso230_3Cli, jsonOfTheMovingRunS1) {
    const CliResult r = iso3({exampleBundlePath(), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject o = json(r);
    EXPECT_EQ(o.value(QStringLiteral("standard")).toString(), QStringLiteral("ISO 230-3"));
    EXPECT_EQ(o.value(QStringLiteral("window_s")).toDouble(), 600);
    EXPECT_EQ(o.value(QStringLiteral("tolerance_um")).toDouble(), 1);
    EXPECT_EQ(o.value(QStringLiteral("runs")).toArray().size(), 2);
    const QJsonObject s1 = runOf(o, QStringLiteral("S1"));
    EXPECT_EQ(s1.value(QStringLiteral("kind")).toString(), QStringLiteral("moving"));
    EXPECT_EQ(s1.value(QStringLiteral("cycles")).toInt(), 7);
    EXPECT_EQ(s1.value(QStringLiteral("far_end_mm")).toDouble(), 700);
    // 700 mm '+': 3.0 µm cold at 20 s, 33.11 µm at cycle 4 (2370 s): 30.11.
    EXPECT_NEAR(s1.value(QStringLiteral("max_drift_um")).toDouble(), 30.11, 1e-9);
    EXPECT_EQ(s1.value(QStringLiteral("max_drift_target_mm")).toDouble(), 700);
    EXPECT_EQ(s1.value(QStringLiteral("max_drift_direction")).toString(), QStringLiteral("+"));
    EXPECT_EQ(s1.value(QStringLiteral("max_drift_time_s")).toDouble(), 2370);
    EXPECT_FALSE(s1.value(QStringLiteral("stabilised")).toBool());
    EXPECT_TRUE(s1.value(QStringLiteral("stabilised_time_s")).isNull());
    const QJsonArray targets = s1.value(QStringLiteral("targets")).toArray();
    ASSERT_EQ(targets.size(), 22);
    const QJsonObject far = targets[21].toObject();
    EXPECT_EQ(far.value(QStringLiteral("direction")).toString(), QStringLiteral("-"));
    // 700 mm '-': 5.15 cold, 34.98 at 2372 s: 29.83; 17.2 at the end: 12.05.
    EXPECT_EQ(far.value(QStringLiteral("max_drift_um")).toDouble(), 29.83);
    EXPECT_EQ(far.value(QStringLiteral("final_drift_um")).toDouble(), 12.05);
    EXPECT_EQ(far.value(QStringLiteral("time_s")).toArray().size(), 7);
    EXPECT_EQ(far.value(QStringLiteral("drift_um")).toArray()[0].toDouble(), 0);
    // The far end drifts more than the zero (the screw grows from its fixed end).
    const QJsonObject zero = s1.value(QStringLiteral("zero")).toObject();
    const QJsonObject farEnd = s1.value(QStringLiteral("far_end")).toObject();
    EXPECT_EQ(farEnd[QStringLiteral("-")][QStringLiteral("max_drift_um")].toDouble(), 29.83);
    for (const char* d : {"+", "-"})
        EXPECT_GT(farEnd[QLatin1String(d)][QStringLiteral("max_drift_um")].toDouble(),
                  zero[QLatin1String(d)][QStringLiteral("max_drift_um")].toDouble() + 10);
}

TEST(Iso230_3Cli, jsonOfTheSpindleRunSP1WithAndWithoutTilts) {
    const CliResult r = iso3({exampleBundlePath(), QStringLiteral("--run"), QStringLiteral("SP1"),
                              QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject o = json(r);
    ASSERT_EQ(o.value(QStringLiteral("runs")).toArray().size(), 1);
    const QJsonObject sp1 = runOf(o, QStringLiteral("SP1"));
    EXPECT_EQ(sp1.value(QStringLiteral("kind")).toString(), QStringLiteral("spindle"));
    const QJsonArray probes = sp1.value(QStringLiteral("probes")).toArray();
    ASSERT_EQ(probes.size(), 5);
    const QJsonObject z = probes[2].toObject();
    EXPECT_EQ(z.value(QStringLiteral("channel")).toString(), QStringLiteral("D_z"));
    EXPECT_EQ(z.value(QStringLiteral("role")).toString(), QStringLiteral("drift_z"));
    EXPECT_EQ(z.value(QStringLiteral("samples")).toInt(), 181);
    EXPECT_LT(z.value(QStringLiteral("max_drift_um")).toDouble(), -10);
    EXPECT_TRUE(sp1.value(QStringLiteral("tilts")).toArray().isEmpty());
    EXPECT_EQ(sp1.value(QStringLiteral("notes")).toArray().size(), 1);

    const CliResult tilted = iso3({exampleBundlePath(), QStringLiteral("--run"),
                                   QStringLiteral("SP1"), QStringLiteral("--probe-distance-mm"),
                                   QStringLiteral("100"), QStringLiteral("--json")});
    ASSERT_EQ(tilted.exitCode, 0) << tilted.err.constData();
    const QJsonArray tilts =
        runOf(json(tilted), QStringLiteral("SP1")).value(QStringLiteral("tilts")).toArray();
    ASSERT_EQ(tilts.size(), 2);
    const QJsonObject a = tilts[0].toObject();
    EXPECT_EQ(a.value(QStringLiteral("name")).toString(), QStringLiteral("A"));
    // µm over 100 mm: 1 µm is 10 µrad.
    EXPECT_NEAR(a.value(QStringLiteral("max_tilt_urad")).toDouble(),
                a.value(QStringLiteral("max_drift_um")).toDouble() * 10, 1e-6);
}

TEST(Iso230_3Cli, textAndTheDatabaseAgreeWithTheBundle) {
    const CliResult text = iso3({exampleBundlePath()});
    ASSERT_EQ(text.exitCode, 0) << text.err.constData();
    EXPECT_TRUE(text.out.contains("DriftLab's criterion"));
    EXPECT_TRUE(
        text.out.contains("axis: max drift 30.110 µm at 700 mm '+', t = 2370 s; "
                          "not stabilised within the run"));
    EXPECT_TRUE(text.out.contains(" D_z        drift_z"));

    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("lab.sqlite"));
    ASSERT_EQ(runCli({QStringLiteral("import"), exampleBundlePath(), QStringLiteral("--db"), db})
                  .exitCode,
              0);
    const CliResult stored = iso3({QStringLiteral("--db"), db, QStringLiteral("--campaign"),
                                   QStringLiteral("1"), QStringLiteral("--json")});
    ASSERT_EQ(stored.exitCode, 0) << stored.err.constData();
    const CliResult bundle = iso3({exampleBundlePath(), QStringLiteral("--json")});
    EXPECT_EQ(json(stored).value(QStringLiteral("runs")),
              json(bundle).value(QStringLiteral("runs")));
}

TEST(Iso230_3Cli, usageErrorsExitTwo) {
    CliResult r = iso3({});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(reason(r.err),
              "driftlab-cli iso230-3: give a BUNDLE folder or --db FILE --campaign ID");
    r = iso3({exampleBundlePath(), QStringLiteral("--window-s"), QStringLiteral("0")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(reason(r.err), "driftlab-cli iso230-3: --window-s: '0' is not a positive number");
    r = iso3({exampleBundlePath(), QStringLiteral("--tolerance-um"), QStringLiteral("x")});
    EXPECT_EQ(r.exitCode, 2);
    r = iso3({exampleBundlePath(), QStringLiteral("--run"), QStringLiteral("S9")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, QByteArray());
    EXPECT_EQ(reason(r.err),
              "driftlab-cli iso230-3: --run: no run 'S9' in the campaign (runs: S1, SP1)");
}

TEST(Iso230_3Cli, settingsChangeTheVerdict) {
    // A loose criterion (D = 50 µm over 600 s) finds S1's drift stable from its start.
    const CliResult r =
        iso3({exampleBundlePath(), QStringLiteral("--run"), QStringLiteral("S1"),
              QStringLiteral("--tolerance-um"), QStringLiteral("50"), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject s1 = runOf(json(r), QStringLiteral("S1"));
    EXPECT_TRUE(s1.value(QStringLiteral("stabilised")).toBool());
    EXPECT_EQ(json(r).value(QStringLiteral("tolerance_um")).toDouble(), 50);
}
