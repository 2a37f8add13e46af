// driftlab-cli iso230-2 as scripts use it: the docs/cli.md JSON shape with
// the hand-worked golden values (tests/iso/Iso230TestData.h), CSV as real
// tools write it, a bundle's run, and failures that name file:line:column.

#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab::test;

namespace {

const QString kGolden = QStringLiteral(DRIFTLAB_SOURCE_DIR "/tests/iso/data/golden_3x5.csv");

QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& content) {
    const QString path = dir.filePath(name);
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(content);
    return path;
}

CliResult iso(QStringList args) {
    return runCli(QStringList{QStringLiteral("iso230-2")} + args);
}

}  // namespace

TEST(Iso230Cli, jsonHasTheDesignShapeWithTheGoldenValues) {
    const CliResult r = iso({kGolden, QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject o = json(r);
    // G1 worked by hand: B = 5, B̄ = 3, R↑ = 4, R↓ = 6, R = 9, E↑ = 5, E↓ = 7,
    // E = 8, M = 6, A↑ = 6, A↓ = 12, A = 12 (µm).
    const std::pair<const char*, double> axis[] = {
        {"B", 5},      {"B_mean", 3}, {"R_up", 4}, {"R_down", 6}, {"R", 9},       {"E_up", 5},
        {"E_down", 7}, {"E", 8},      {"M", 6},    {"A_up", 6},   {"A_down", 12}, {"A", 12}};
    for (const auto& [key, value] : axis) {
        ASSERT_TRUE(o.value(QLatin1String(key)).isDouble()) << key;
        EXPECT_NEAR(o.value(QLatin1String(key)).toDouble(), value, 1e-12) << key;
    }
    EXPECT_EQ(o.value(QStringLiteral("edition")).toInt(), 2014);
    EXPECT_EQ(o.value(QStringLiteral("standard")).toString(), QStringLiteral("ISO 230-2:2014"));
    EXPECT_EQ(o.value(QStringLiteral("coverage_factor")).toDouble(), 2);
    EXPECT_EQ(o.value(QStringLiteral("unit")).toString(), QStringLiteral("µm"));
    // G1's three targets are below the standard's five, and its swing common
    // to every target is warned about (tests/iso: 1.67 µm).
    EXPECT_EQ(o.value(QStringLiteral("warnings")).toArray().size(), 2);
    const QJsonArray targets = o.value(QStringLiteral("targets")).toArray();
    ASSERT_EQ(targets.size(), 3);
    // '+' rows are ↑: at 0 mm x̄↑ = 15/5 = 3 (cycles, not targets), x̄↓ = −2,
    // B = +5, and R = 2 + 2 + 5 = 9 beats R↑ = R↓ = 4.
    const QJsonObject first = targets[0].toObject();
    EXPECT_EQ(first.value(QStringLiteral("target_mm")).toDouble(), 0);
    EXPECT_EQ(first.value(QStringLiteral("mean_up")).toDouble(), 3);
    EXPECT_EQ(first.value(QStringLiteral("mean_down")).toDouble(), -2);
    EXPECT_EQ(first.value(QStringLiteral("B")).toDouble(), 5);
    EXPECT_EQ(first.value(QStringLiteral("R_up")).toDouble(), 4);
    EXPECT_EQ(first.value(QStringLiteral("R")).toDouble(), 9);
    EXPECT_EQ(first.value(QStringLiteral("n_up")).toInt(), 5);
    const QJsonObject second = targets[1].toObject();
    EXPECT_EQ(second.value(QStringLiteral("s_down")).toDouble(), 1.5);
    EXPECT_EQ(second.value(QStringLiteral("R")).toDouble(), 6);
}

TEST(Iso230Cli, readsCsvAsPythonsCsvModuleWritesIt) {
    // csv.writer(f, quoting=csv.QUOTE_ALL) with encoding="utf-8-sig": a BOM,
    // every field quoted, CRLF; columns in another order and a bundle's extra
    // run,time_s columns.
    QTemporaryDir dir;
    QFile golden(kGolden);
    ASSERT_TRUE(golden.open(QIODevice::ReadOnly));
    QByteArray csv =
        "\xEF\xBB\xBF\"run\",\"direction\",\"deviation_um\",\"time_s\",\"cycle\","
        "\"target_mm\"\r\n";
    int row = 0;
    for (const QByteArray& line : golden.readAll().trimmed().split('\n').mid(1)) {
        const QList<QByteArray> f = line.split(',');  // target_mm,direction,cycle,deviation_um
        csv += "\"P1\",\"" + f[1] + "\",\"" + f[3] + "\",\"" + QByteArray::number(2 * row++) +
               "\",\"" + f[2] + "\",\"" + f[0] + "\"\r\n";
    }
    const CliResult r =
        iso({writeFile(dir, QStringLiteral("python.csv"), csv), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_EQ(json(r).value(QStringLiteral("E")).toDouble(), 8);
    EXPECT_EQ(json(r).value(QStringLiteral("R")).toDouble(), 9);
    EXPECT_EQ(json(r).value(QStringLiteral("B")).toDouble(), 5);
}

TEST(Iso230Cli, textNamesEditionCoverageFactorAndUnits) {
    const CliResult r = iso({kGolden, QStringLiteral("--edition"), QStringLiteral("1997")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_TRUE(r.out.startsWith("ISO 230-2:1997 evaluation of ")) << r.out.constData();
    EXPECT_TRUE(r.out.contains("coverage factor k = 2 (R↑_i = 4·s↑_i")) << r.out.constData();
    EXPECT_TRUE(
        r.out.contains("\n   100.000      4.000      3.000      0.500      1.500      1.000"
                       "      2.000      6.000      6.000\n"))
        << r.out.constData();
    EXPECT_TRUE(r.out.contains("  R    bidirectional repeatability                     9.000 µm\n"))
        << r.out.constData();
    EXPECT_TRUE(r.out.contains("  E    bidirectional systematic error                  8.000 µm\n"))
        << r.out.constData();
}

TEST(Iso230Cli, coverageFactorIsAnOption) {
    const CliResult r = iso({kGolden, QStringLiteral("--coverage-factor"), QStringLiteral("3"),
                             QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_EQ(json(r).value(QStringLiteral("coverage_factor")).toDouble(), 3);
    EXPECT_EQ(json(r).value(QStringLiteral("R")).toDouble(), 11);  // 3 + 3 + 5
}

TEST(Iso230Cli, badDirectionNamesFileLineAndColumn) {
    QTemporaryDir dir;
    const QString path = writeFile(dir, QStringLiteral("bad.csv"),
                                   "target_mm,direction,cycle,deviation_um\n"
                                   "0,+,1,2\n"
                                   "0,both,2,4\n");
    const CliResult r = iso({path});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.out, QByteArray());
    EXPECT_EQ(reason(r.err), "driftlab-cli iso230-2: " + path.toUtf8() +
                                 ":3:2: direction must be '+' (positive approach, ↑) or '-' "
                                 "(negative approach, ↓), not 'both'");
}

TEST(Iso230Cli, missingColumnAndTooFewReadingsAreNamed) {
    QTemporaryDir dir;
    const QString noCycle =
        writeFile(dir, QStringLiteral("nocycle.csv"), "target_mm,direction,deviation_um\n0,+,2\n");
    CliResult r = iso({noCycle});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(reason(r.err), "driftlab-cli iso230-2: " + noCycle.toUtf8() +
                                 ":1: missing column 'cycle' in header");
    const QString once = writeFile(dir, QStringLiteral("once.csv"),
                                   "target_mm,direction,cycle,deviation_um\n"
                                   "0,+,1,2\n0,+,2,3\n0,-,1,1\n"
                                   "100,+,1,2\n100,+,2,3\n100,-,1,1\n100,-,2,1\n");
    r = iso({once});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(reason(r.err), "driftlab-cli iso230-2: " + once.toUtf8() +
                                 ": target 0 mm, direction - (↓): 1 reading, the standard "
                                 "deviation s needs at least 2 (ISO 230-2 allows one approach "
                                 "per direction only on axes over 2000 mm; this travel is 100 mm)");
}

TEST(Iso230Cli, theStandardsMinimumsAreRefusedOrWarnedAndNamed) {
    QTemporaryDir dir;
    // One target: E, M and A compare targets, nothing to evaluate.
    QByteArray single = "target_mm,direction,cycle,deviation_um\n";
    for (int c = 1; c <= 5; ++c)
        single += QByteArray("0,+,") + QByteArray::number(c) + ",1\n0,-," + QByteArray::number(c) +
                  ",2\n";
    const QString one = writeFile(dir, QStringLiteral("one.csv"), single);
    CliResult r = iso({one});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(reason(r.err), "driftlab-cli iso230-2: " + one.toUtf8() +
                                 ": one target (0 mm): E, M and A compare targets, so at least 2 "
                                 "are needed; ISO 230-2 asks for at least 5");
    // A negative cycle and a target no machine has: refused at their cell.
    const QString negative = writeFile(dir, QStringLiteral("negative.csv"),
                                       "target_mm,direction,cycle,deviation_um\n0,+,-1,2\n");
    r = iso({negative});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(reason(r.err),
              "driftlab-cli iso230-2: " + negative.toUtf8() +
                  ":2:3: value '-1' in column 'cycle' is out of range: an integer from 0 to "
                  "2147483647 is expected");
    const QString far = writeFile(dir, QStringLiteral("far.csv"),
                                  "target_mm,direction,cycle,deviation_um\n1e300,+,1,2\n");
    r = iso({far});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(reason(r.err), "driftlab-cli iso230-2: " + far.toUtf8() +
                                 ":2:1: target 1e+300 mm is beyond any machine's travel (±100000 "
                                 "mm)");
    // Two targets, two approaches each: evaluated, and both shortfalls named.
    const QString few = writeFile(dir, QStringLiteral("few.csv"),
                                  "target_mm,direction,cycle,deviation_um\n"
                                  "0,+,1,2\n0,+,2,3\n0,-,1,1\n0,-,2,1\n"
                                  "1000,+,1,2\n1000,+,2,3\n1000,-,1,1\n1000,-,2,1\n");
    r = iso({few, QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonArray warnings = json(r).value(QStringLiteral("warnings")).toArray();
    EXPECT_TRUE(warnings.contains(QStringLiteral(
        "below ISO 230-2's minimum: 2 targets over 1000 mm; at least 5 are needed (five, and "
        "five per metre)")))
        << r.out.constData();
    EXPECT_TRUE(warnings.contains(QStringLiteral(
        "below ISO 230-2's minimum: 2 approaches at target 0 mm, direction + (↑); five per "
        "direction at every target are needed")))
        << r.out.constData();
    EXPECT_TRUE(r.err.contains("warning: below ISO 230-2's minimum: 2 targets"))
        << r.err.constData();
}

TEST(Iso230Cli, usageErrorsExitTwo) {
    CliResult r = iso({kGolden, QStringLiteral("--edition"), QStringLiteral("1988")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "driftlab-cli iso230-2: --edition: '1988' is not 2014, 2006 or 1997\n");
    r = iso({});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(reason(r.err),
              "driftlab-cli iso230-2: give a CSV file, a BUNDLE or --db FILE --campaign ID");
    r = iso({kGolden, QStringLiteral("--coverage-factor"), QStringLiteral("-1")});
    EXPECT_EQ(r.exitCode, 2);
}

TEST(Iso230Cli, evaluatesTheRunOfABundleAndWarnsOfItsThermalDrift) {
    const CliResult r = iso({exampleBundlePath(), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject o = json(r);
    EXPECT_TRUE(o.value(QStringLiteral("source")).toString().startsWith(QStringLiteral("run S1")));
    EXPECT_EQ(o.value(QStringLiteral("targets")).toArray().size(), 11);
    // A moving-state run warms the axis up between cycles: that is drift, not
    // repeatability, and the warning says so with its numbers.
    const QJsonArray warnings = o.value(QStringLiteral("warnings")).toArray();
    ASSERT_EQ(warnings.size(), 1);
    EXPECT_TRUE(warnings[0].toString().startsWith(
        QStringLiteral("deviations drift from cycle to cycle: the per-cycle mean deviation "
                       "spans ")));
    EXPECT_TRUE(r.err.contains("warning: deviations drift from cycle to cycle"));
    const CliResult wrongRun =
        iso({exampleBundlePath(), QStringLiteral("--run"), QStringLiteral("S9")});
    EXPECT_EQ(wrongRun.exitCode, 2);
    EXPECT_EQ(reason(wrongRun.err),
              "driftlab-cli iso230-2: --run: no run 'S9' in the campaign (runs: S1, SP1)");
}

TEST(Iso230Cli, evaluatesARunOfTheDatabaseAsOfItsBundle) {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("lab.sqlite"));
    ASSERT_EQ(runCli({QStringLiteral("import"), exampleBundlePath(), QStringLiteral("--db"), db})
                  .exitCode,
              0);
    const CliResult stored = iso({QStringLiteral("--db"), db, QStringLiteral("--campaign"),
                                  QStringLiteral("1"), QStringLiteral("--json")});
    ASSERT_EQ(stored.exitCode, 0) << stored.err.constData();
    const CliResult bundle = iso({exampleBundlePath(), QStringLiteral("--json")});
    for (const char* key : {"B", "R", "E", "M", "A"})
        EXPECT_EQ(json(stored).value(QLatin1String(key)), json(bundle).value(QLatin1String(key)))
            << key;
}
