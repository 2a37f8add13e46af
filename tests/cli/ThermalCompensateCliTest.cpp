// compensate with a model's thermal error at a stated state: the table's
// thermal part is checked against the thermal error the interferometer
// measured in that (held-out) run at that time; the straight-line formats
// carry most of it from the screw's fixed end; refusals name what is missing.

#include <gtest/gtest.h>

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <map>

#include "core/bundle/BundleReader.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

const QString& campaignS1S3() {
    return simulatedCampaign(QStringLiteral("S1,S3"), 5);
}

/// position → correction µm of a CSV table.
std::map<double, double> csvTable(const QString& path) {
    std::map<double, double> table;
    const QList<QByteArray> lines = readFile(path).trimmed().split('\n');
    for (int i = 1; i < lines.size(); ++i) {
        const QList<QByteArray> f = lines[i].split(',');
        table[f[0].toDouble()] = f[1].toDouble();
    }
    return table;
}

}  // namespace

TEST(ThermalCompensateCli, theThermalPartIsMinusTheErrorMeasuredInTheHeldOutRunAtThatTime) {
    const auto read = bundle::readBundle(campaignS1S3());
    ASSERT_TRUE(read.ok());
    const driftlab::Run* s3 = nullptr;
    for (const driftlab::Run& run : read.campaign->runs)
        if (run.id == QLatin1String("S3")) s3 = &run;
    ASSERT_NE(s3, nullptr);
    // The state: S3's cycle 8, warm. Measured thermal error per target:
    // deviation at that cycle − deviation at cycle 0, averaged over both directions.
    const int cycle = 8;
    std::map<double, double> cold, warm, count;
    double time_s = 0;
    for (const PositioningMeasurement& m : s3->positioning) {
        if (m.cycle == 0) cold[m.target_mm] += m.deviation_um;
        if (m.cycle == cycle) {
            warm[m.target_mm] += m.deviation_um;
            count[m.target_mm] += 1;
            time_s = std::max(time_s, m.time_s);
        }
    }
    ASSERT_FALSE(warm.empty());
    QTemporaryDir dir;
    const QString coldCsv = dir.filePath("cold.csv"), warmCsv = dir.filePath("warm.csv");
    const QStringList base{"compensate", campaignS1S3(), "--run", "S1", "--format", "csv"};
    CliResult r = runCli(base + QStringList{"--out", coldCsv});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QString at = QStringLiteral("S3@%1").arg(time_s);
    r = runCli(base + QStringList{"--out", warmCsv, "--model", "heat-transfer", "--train", "S1",
                                  "--at", at, "--max-value-um", "300", "--max-step-um", "100",
                                  "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_TRUE(QJsonDocument::fromJson(r.out)["thermal"].toString().contains(
        QStringLiteral("at S3 t = %1 s").arg(time_s)));
    const auto coldTable = csvTable(coldCsv), warmTable = csvTable(warmCsv);
    ASSERT_EQ(coldTable.size(), warmTable.size());
    int compared = 0;
    double largest_um = 0;
    for (const auto& [x, correction] : warmTable) {
        if (!warm.count(x)) continue;
        const double measured_um = (warm[x] - cold[x]) / count[x];
        const double thermalPart_um = correction - coldTable.at(x);
        // The model was fitted on S1 only: within 3 µm of S3's measurement.
        EXPECT_NEAR(thermalPart_um, -measured_um, 3) << "at " << x << " mm";
        largest_um = std::max(largest_um, std::abs(measured_um));
        ++compared;
    }
    EXPECT_GE(compared, 5);
    EXPECT_GT(largest_um, 15);  // a state worth compensating
}

TEST(ThermalCompensateCli, theTemperatureLineStartsAtTheFixedEndAndSaysWhatItLeaves) {
    QTemporaryDir dir;
    const QString out = dir.filePath("temp.spf");
    const CliResult r =
        runCli({"compensate", campaignS1S3(), "--run", "S1", "--format", "sinumerik-temp", "--out",
                out, "--axis", "X1", "--model", "heat-transfer", "--at", "S3@7200", "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject line = QJsonDocument::fromJson(r.out)["line"].toObject();
    const double slope = line["slope_um_per_m"].toDouble();
    EXPECT_GT(slope, 20);  // the warm screw grows away from its fixed end
    EXPECT_DOUBLE_EQ(line["reference_mm"].toDouble(), -40);  // the simulated rig's fixed end
    // Growth starts at the fixed end: the line's error there is small next to
    // what it reaches over the 700 mm of travel.
    EXPECT_LT(std::abs(line["offset_um"].toDouble()), 0.2 * slope * 0.7);
    EXPECT_LT(line["residual_rms_um"].toDouble(), 0.3 * slope * 0.7);
    const QByteArray text = readFile(out);
    EXPECT_TRUE(
        text.contains("$SA_TEMP_COMP_SLOPE[X1]=" + QByteArray::number(slope * 1e-6, 'f', 8)))
        << text.constData();
}

TEST(ThermalCompensateCli, aLineFormatNeedsAModelAndAStateAndIsNeverPushed) {
    QTemporaryDir dir;
    const QStringList base{"compensate", campaignS1S3(), "--run", "S1",
                           "--format",   "isg-temp",     "--out", dir.filePath("x")};
    CliResult r = runCli(base);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(reason(r.err).contains("--model")) << r.err.constData();
    r = runCli(base + QStringList{"--model", "heat-transfer", "--at", "S3@7200", "--push",
                                  "modbus://127.0.0.1:1"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(reason(r.err).contains("--push")) << r.err.constData();
    r = runCli(base + QStringList{"--model", "heat-transfer", "--at", "S3@1e9"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(reason(r.err).contains("ends at")) << r.err.constData();
    EXPECT_FALSE(QFile::exists(dir.filePath("x")));
}
