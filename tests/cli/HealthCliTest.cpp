// driftlab-cli health on the example bundle: nothing found on the data as
// logged; faults written into a copy of its samples.csv, as a broken sensor
// would have logged them, are each found on their channel, kind and time.

#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab::test;

namespace {

QJsonObject health(const QString& bundle) {
    const CliResult r = runCli({"health", bundle, "--json"});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return QJsonDocument::fromJson(r.out).object();
}

/// The findings of `channel` in run `run`.
QJsonArray findings(const QJsonObject& report, const QString& run, const QString& channel) {
    for (const QJsonValue& r : report["runs"].toArray())
        if (r["id"].toString() == run)
            for (const QJsonValue& c : r["channels"].toArray())
                if (c["id"].toString() == channel) return c["findings"].toArray();
    ADD_FAILURE() << "no channel " << qPrintable(channel) << " in run " << qPrintable(run);
    return {};
}

}  // namespace

TEST(HealthCli, theExampleAsLoggedHasNoFinding) {
    const QJsonObject report = health(exampleBundlePath());
    EXPECT_TRUE(report["healthy"].toBool());
    EXPECT_EQ(report["runs"].toArray().size(), 2);
}

TEST(HealthCli, aFrozenAShortedAndAnEmiHitSensorAreEachFoundWhereTheyHappened) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath("broken");
    copyBundle(exampleBundlePath(), bundle);
    QList<QByteArray> lines = readFile(bundle + "/samples.csv").split('\n');
    const QList<QByteArray> header = lines[0].split(',');
    const int frozenColumn = int(header.indexOf("T_bearing_free"));
    const int shortColumn = int(header.indexOf("T_ambient"));
    const int spikeColumn = int(header.indexOf("T_air"));
    for (int i = 1; i < lines.size(); ++i) {
        QList<QByteArray> f = lines[i].split(',');
        if (f.size() < header.size() || f[0] != "S1") continue;
        const double t = f[1].toDouble();
        if (t >= 1200 && t <= 1800) f[frozenColumn] = "21.37";  // stuck for 10 min
        if (t == 2400) f[shortColumn] = "-50";                  // shorted element, clamped
        if (t == 3000) f[spikeColumn] = QByteArray::number(f[spikeColumn].toDouble() + 5);
        lines[i] = f.join(',');
    }
    writeFile(bundle + "/samples.csv", lines.join('\n'));

    const QJsonObject report = health(bundle);
    EXPECT_FALSE(report["healthy"].toBool());
    const QJsonArray frozen = findings(report, "S1", "T_bearing_free");
    ASSERT_EQ(frozen.size(), 1);
    EXPECT_EQ(frozen[0]["kind"].toString(), "frozen");
    const QJsonArray range = frozen[0]["ranges_s"].toArray()[0].toArray();
    EXPECT_LE(range[0].toDouble(), 1200);
    EXPECT_GE(range[1].toDouble(), 1800);
    const QJsonArray shorted = findings(report, "S1", "T_ambient");
    ASSERT_EQ(shorted.size(), 1);
    EXPECT_EQ(shorted[0]["kind"].toString(), "out_of_range");
    EXPECT_EQ(shorted[0]["samples"].toInt(), 1);
    const QJsonArray spike = findings(report, "S1", "T_air");
    ASSERT_EQ(spike.size(), 1);
    EXPECT_EQ(spike[0]["kind"].toString(), "spike");
    EXPECT_EQ(spike[0]["ranges_s"].toArray()[0].toArray()[0].toDouble(), 3000);
    // The sensors left alone, and the other run, have nothing.
    EXPECT_TRUE(findings(report, "S1", "T_bearing_fixed").isEmpty());
    EXPECT_TRUE(findings(report, "SP1", "T_bearing_free").isEmpty());

    const CliResult text = runCli({"health", bundle, "--run", "S1"});
    EXPECT_TRUE(text.out.contains("S1  T_bearing_free: frozen")) << text.out.constData();
}

TEST(HealthCli, aRunOrPairThatIsNotThereIsAUsageError) {
    CliResult r = runCli({"health", exampleBundlePath(), "--run", "S9"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(reason(r.err).contains("S9")) << r.err.constData();
    r = runCli({"health", exampleBundlePath(), "--redundant", "T_nut"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(reason(r.err).contains("A=B")) << r.err.constData();
}
