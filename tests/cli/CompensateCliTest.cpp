// driftlab-cli compensate as a test engineer uses it on the example bundle:
// every format written, the LinuxCNC file as LinuxCNC reads it, the CSV equal
// to minus the ISO 230-2 mean deviations, and refusals that name the point
// and value (a limit) or the missing readings. The push: PushCliTest.cpp.

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <cmath>

#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab::test;

namespace {

CliResult compensate(QStringList args) {
    return runCli(QStringList{QStringLiteral("compensate"), exampleBundlePath()} + args);
}

/// Runs compensate into dir/name and returns the file, failing on any error.
QByteArray exported(const QTemporaryDir& dir, const QString& format, const QString& name,
                    QStringList more = {}) {
    const QString out = dir.filePath(name);
    const CliResult r =
        compensate(QStringList{"--format", format, "--out", out, "--spacing", "35"} + more);
    EXPECT_EQ(r.exitCode, 0) << qPrintable(format) << ": " << r.err.constData();
    return readFile(out);
}

/// x̄_i of the example's run S1 per target, from iso230-2 --json; with
/// `uncertainty`, instead the expanded uncertainty of x̄_i from its cycles,
/// 2 · ½·√(s↑²/n↑ + s↓²/n↓).
std::vector<std::pair<double, double>> meanDeviations(bool uncertainty = false) {
    const CliResult r =
        runCli({QStringLiteral("iso230-2"), exampleBundlePath(), QStringLiteral("--json")});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    std::vector<std::pair<double, double>> means;
    for (const QJsonValue& t : QJsonDocument::fromJson(r.out).object()["targets"].toArray())
        means.emplace_back(
            t["target_mm"].toDouble(),
            uncertainty ? std::hypot(t["s_up"].toDouble() / std::sqrt(t["n_up"].toDouble()),
                                     t["s_down"].toDouble() / std::sqrt(t["n_down"].toDouble()))
                        : t["mean"].toDouble());
    return means;
}

double interpolated(const std::vector<std::pair<double, double>>& points, double x) {
    for (std::size_t i = 1; i < points.size(); ++i)
        if (x <= points[i].first + 1e-9) {
            const auto [x0, y0] = points[i - 1];
            const auto [x1, y1] = points[i];
            return y0 + (x - x0) / (x1 - x0) * (y1 - y0);
        }
    return points.back().second;
}

}  // namespace

TEST(CompensateCli, csvIsMinusTheInterpolatedIsoMeanDeviations) {
    QTemporaryDir dir;
    const QByteArray csv = exported(dir, "csv", "x.csv");
    QList<QByteArray> lines = csv.trimmed().split('\n');
    ASSERT_EQ(lines.takeFirst(), QByteArray("position_mm,correction_um,uncertainty_um"));
    const auto means = meanDeviations();
    const auto uncertainties = meanDeviations(true);
    ASSERT_GE(means.size(), 2u);
    ASSERT_EQ(lines.size(), 21);  // 0 to 700 mm every 35 mm
    for (const QByteArray& line : lines) {
        const QList<QByteArray> fields = line.split(',');
        ASSERT_EQ(fields.size(), 3) << line.constData();
        const double x = fields[0].toDouble();
        EXPECT_NEAR(fields[1].toDouble(), -interpolated(means, x), 0.0005 + 1e-9)
            << line.constData();
        EXPECT_NEAR(fields[2].toDouble(), interpolated(uncertainties, x), 0.0005 + 1e-9)
            << line.constData();
    }
}

TEST(CompensateCli, linuxCncFileIsReadableByLinuxCnc) {
    QTemporaryDir dir;
    for (const QString& format : {QStringLiteral("linuxcnc"), QStringLiteral("linuxcnc-type1")}) {
        const QByteArray text = exported(dir, format, format + ".comp");
        ASSERT_TRUE(text.endsWith('\n'));
        const QList<QByteArray> rows = text.chopped(1).split('\n');
        EXPECT_EQ(rows.size(), 21);
        double previous = -1e300;
        for (const QByteArray& row : rows) {
            const QList<QByteArray> fields = row.split(' ');
            ASSERT_EQ(fields.size(), 3) << row.constData();
            for (const QByteArray& f : fields) {
                bool ok = false;
                f.toDouble(&ok);
                EXPECT_TRUE(ok) << row.constData();
            }
            EXPECT_GT(fields[0].toDouble(), previous);
            previous = fields[0].toDouble();
        }
        EXPECT_FALSE(text.contains('#') || text.contains(';') || text.contains("\n\n"));
    }
}

TEST(CompensateCli, everyFormatIsWrittenAndRepeatable) {
    QTemporaryDir dir;
    const QByteArray fanuc = exported(dir, "fanuc", "x.prm");
    EXPECT_TRUE(fanuc.startsWith("%\nN01851A1P")) << fanuc.constData();
    EXPECT_TRUE(
        fanuc.contains("\nN03620A1P0\nN03621A1P1\nN03622A1P20\nN03623A1P1\nN03624A1P35000\n"))
        << fanuc.constData();
    EXPECT_TRUE(fanuc.contains("\nN10020P")) << fanuc.constData();
    EXPECT_TRUE(fanuc.endsWith("%\n"));
    const QByteArray g10 = exported(dir, "fanuc-g10", "x.nc");
    EXPECT_TRUE(g10.contains("\nG10 L50\nN10001 R")) << g10.constData();
    EXPECT_TRUE(g10.endsWith("\nG11\nM30\n%\n"));
    const QByteArray eec = exported(dir, "sinumerik", "x.ini", {"--axis", "X1"});
    EXPECT_TRUE(eec.startsWith("%_N_AX_EEC_INI\nCHANDATA(1)\n$AA_ENC_COMP[0,0,X1]="));
    EXPECT_TRUE(
        eec.endsWith("$AA_ENC_COMP_STEP[0,X1]=35.0000\n$AA_ENC_COMP_MIN[0,X1]=0.0000\n"
                     "$AA_ENC_COMP_MAX[0,X1]=700.0000\n$AA_ENC_COMP_IS_MODULO[0,X1]=0\n"
                     "M17\n"))
        << eec.constData();
    const QByteArray com = exported(dir, "heidenhain", "x.com");
    EXPECT_TRUE(com.startsWith("BEGIN X.COM MM\nNR    AXISPOS         X               BACKLASH\n"))
        << com.constData();
    EXPECT_TRUE(com.endsWith("\n[END]\n"));
    EXPECT_EQ(com.count('\n'), 2 + 21 + 1);
    // The same input gives the same bytes: a table can be diffed and re-sent.
    EXPECT_EQ(exported(dir, "fanuc", "again.prm"), fanuc);
}

TEST(CompensateCli, jsonSummaryHasPointsRangeMaxAndBacklash) {
    QTemporaryDir dir;
    const CliResult r =
        compensate({"--format", "csv", "--out", dir.filePath("t.csv"), "--points", "11", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject json = QJsonDocument::fromJson(r.out).object();
    EXPECT_EQ(json["points"].toInt(), 11);
    EXPECT_EQ(json["start_mm"].toDouble(), 0);
    EXPECT_EQ(json["end_mm"].toDouble(), 700);
    EXPECT_EQ(json["spacing_mm"].toDouble(), 70);
    EXPECT_GT(json["max_correction_um"].toDouble(), 0);
    EXPECT_TRUE(json["B_mean_um"].isDouble());
    EXPECT_EQ(json["run"].toString(), QStringLiteral("S1"));
}

TEST(CompensateCli, limitExceededNamesPointAndValueAndWritesNothing) {
    QTemporaryDir dir;
    const QString out = dir.filePath("x.comp");
    // x̄ at 0 mm is 1.646 µm: the first point already breaks a 1 µm limit.
    const CliResult r = compensate({"--format", "linuxcnc", "--out", out, "--max-value-um", "1"});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(reason(r.err),
              QByteArray("driftlab-cli compensate: run S1 of X axis moving-state example: point 0 "
                         "at 0.000 mm: correction -1.646 µm exceeds the limit ±1.000 µm (max "
                         "value)"));
    EXPECT_FALSE(QFile::exists(out));
}

TEST(CompensateCli, tooManyPointsForLinuxCncNamesTheLimit) {
    QTemporaryDir dir;
    const CliResult r =
        compensate({"--format", "linuxcnc", "--out", dir.filePath("x.comp"), "--points", "300"});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(reason(r.err), QByteArray("driftlab-cli compensate: linuxcnc: LinuxCNC takes at most "
                                        "256 compensation rows per joint; this table has 300 "
                                        "points: use a larger spacing"));
}

TEST(CompensateCli, runWithoutPositioningReadingsIsAClearError) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath("bundle");
    copyBundle(exampleBundlePath(), bundle);
    writeFile(bundle + "/positioning.csv", "run,time_s,cycle,target_mm,direction,deviation_um\n");
    const CliResult r =
        runCli({"compensate", bundle, "--format", "csv", "--out", dir.filePath("x.csv")});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(
        reason(r.err),
        QByteArray("driftlab-cli compensate: no run of the campaign has positioning readings"));
    const CliResult named = runCli(
        {"compensate", bundle, "--run", "S1", "--format", "csv", "--out", dir.filePath("x.csv")});
    EXPECT_EQ(reason(named.err),
              QByteArray("driftlab-cli compensate: run S1 has no positioning readings"));
}

TEST(CompensateCli, unknownFormatIsAUsageError) {
    const CliResult r = compensate({"--format", "okuma", "--out", "x"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(reason(r.err).contains("--format: 'okuma' is not one of linuxcnc,"))
        << r.err.constData();
}
