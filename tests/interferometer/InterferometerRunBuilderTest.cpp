// A vendor's CSV export read through a column mapping and turned into an
// ISO 230-2 positioning run: targets, directions and cycles assigned from the
// sequence of readings alone, and what cannot be assigned refused by line.
#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>

#include "core/interferometer/InterferometerCsvImport.h"
#include "core/interferometer/InterferometerRunBuilder.h"
#include "tests/support/VendorInterferometerCsv.h"

using namespace driftlab;

const std::vector<double> kVendorTargets{50, 150, 250, 350, 450};

/// The vendor export written to a file and read with the error column mapped.
struct VendorExport {
    QTemporaryDir dir;
    QString path = dir.filePath(QStringLiteral("laser-export.csv"));

    interferometer::InterferometerCsvImport read(const QByteArray& text) {
        QFile file(path);
        EXPECT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(text);
        file.close();
        interferometer::ColumnMapping mapping;
        mapping[interferometer::ReadingRole::Deviation] = QStringLiteral("Error [µm]");
        return interferometer::importInterferometerCsv(path, interferometer::InterferometerHeader{},
                                                       mapping);
    }
};

interferometer::PositioningRunContext vendorContext() {
    interferometer::PositioningRunContext c;
    c.fileName = QStringLiteral("laser-export.csv");
    c.campaignName = QStringLiteral("X ISO 230-2");
    c.machine = QStringLiteral("VMC 1");
    c.axis = QStringLiteral("X");
    c.runId = QStringLiteral("P1");
    return c;
}

TEST(InterferometerRunBuilder, assignsTargetsDirectionsAndCyclesOfAVendorExport) {
    const std::vector<test::VendorReading> expected = test::vendorReadings(kVendorTargets, 2);
    VendorExport file;
    const interferometer::InterferometerCsvImport imported = file.read(test::vendorCsv(expected));
    ASSERT_FALSE(imported.error) << imported.error->toString().toStdString();
    ASSERT_EQ(imported.readings.size(), expected.size());

    EXPECT_EQ(interferometer::clusterTargets(imported.readings, 0.5), kVendorTargets);
    const interferometer::PositioningRunBuild build =
        interferometer::buildPositioningCampaign(imported.readings, vendorContext());
    ASSERT_FALSE(build.error) << build.error->toString().toStdString();
    const Campaign& c = *build.campaign;
    EXPECT_EQ(c.name, QStringLiteral("X ISO 230-2"));
    EXPECT_EQ(c.machine.axis, QStringLiteral("X"));
    ASSERT_EQ(c.runs.size(), 1u);
    const driftlab::Run& run = c.runs.front();
    EXPECT_EQ(run.kind, RunKind::Positioning);
    EXPECT_EQ(run.range_mm, (RangeMm{50, 450}));
    ASSERT_EQ(run.positioning.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const PositioningMeasurement& m = run.positioning[i];
        EXPECT_EQ(m.target_mm, expected[i].target_mm) << "reading " << i;
        EXPECT_EQ(m.direction, expected[i].positive ? Direction::Positive : Direction::Negative)
            << "reading " << i;
        EXPECT_EQ(m.cycle, expected[i].cycle) << "reading " << i;
        EXPECT_NEAR(m.deviation_um, expected[i].error_um, 1e-9) << "reading " << i;
        EXPECT_NEAR(m.time_s, expected[i].time_s, 1e-9) << "reading " << i;
    }
}

TEST(InterferometerRunBuilder, givenTargetsAreUsedAsGiven) {
    VendorExport file;
    const auto imported = file.read(test::vendorCsv(test::vendorReadings(kVendorTargets, 2)));
    ASSERT_FALSE(imported.error);
    auto context = vendorContext();
    context.targets_mm = {450, 50, 250, 150, 350};  // in any order
    const auto build = interferometer::buildPositioningCampaign(imported.readings, context);
    ASSERT_FALSE(build.error) << build.error->toString().toStdString();
    EXPECT_EQ(build.campaign->runs.front().positioning[7].target_mm, 250.0);
    EXPECT_EQ(build.campaign->runs.front().positioning[7].direction, Direction::Negative);
}

TEST(InterferometerRunBuilder, aReadingFarFromEveryTargetIsRefusedByItsLine) {
    std::vector<test::VendorReading> readings = test::vendorReadings(kVendorTargets, 2);
    // Between the cycles the axis stopped at 300 mm and the software logged it:
    // the CSV's line 12 (the header is line 1).
    test::VendorReading stray = readings[9];
    stray.target_mm = 300;
    stray.position_mm = 300.0021;
    stray.error_um = 2.1;
    stray.time_s += 5;
    readings.insert(readings.begin() + 10, stray);
    VendorExport file;
    const auto imported = file.read(test::vendorCsv(readings));
    ASSERT_FALSE(imported.error);

    const auto inferred =
        interferometer::buildPositioningCampaign(imported.readings, vendorContext());
    ASSERT_TRUE(inferred.error);
    EXPECT_FALSE(inferred.campaign);
    EXPECT_EQ(inferred.error->file, QStringLiteral("laser-export.csv"));
    EXPECT_EQ(inferred.error->line, 12);
    EXPECT_TRUE(inferred.error->message.contains(QStringLiteral("at no target")))
        << inferred.error->toString().toStdString();

    auto given = vendorContext();
    given.targets_mm = kVendorTargets;
    const auto refused = interferometer::buildPositioningCampaign(imported.readings, given);
    ASSERT_TRUE(refused.error);
    EXPECT_EQ(refused.error->toString().left(20), QStringLiteral("laser-export.csv:12:"));
    EXPECT_TRUE(refused.error->message.contains(QStringLiteral("from the nearest target 250 mm")))
        << refused.error->toString().toStdString();
}

TEST(InterferometerRunBuilder, readingsAtOneTargetAreNoRun) {
    std::vector<test::VendorReading> readings = test::vendorReadings({100}, 2);
    VendorExport file;
    const auto imported = file.read(test::vendorCsv(readings));
    ASSERT_FALSE(imported.error);
    const auto build = interferometer::buildPositioningCampaign(imported.readings, vendorContext());
    ASSERT_TRUE(build.error);
    EXPECT_EQ(build.error->line, 2);
    EXPECT_TRUE(build.error->message.contains(QStringLiteral("at least 2")))
        << build.error->toString().toStdString();
}

TEST(InterferometerRunBuilder, aMappedColumnTheFileLacksIsNamed) {
    VendorExport file;
    QFile out(file.path);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write("Target [mm];Position (mm);Err;Time [s]\n50;50;1;0\n");
    out.close();
    interferometer::ColumnMapping mapping;
    mapping[interferometer::ReadingRole::Deviation] = QStringLiteral("Error [µm]");
    const auto imported = interferometer::importInterferometerCsv(
        file.path, interferometer::InterferometerHeader{}, mapping);
    ASSERT_TRUE(imported.error);
    EXPECT_EQ(imported.error->toString(),
              QStringLiteral("laser-export.csv:1: missing column 'Error [µm]' (chosen for "
                             "deviation_um) in header"));
}

TEST(InterferometerColumns, vendorHeadersArePreselected) {
    const std::vector<QString> header{
        QStringLiteral("Target [mm]"),   QStringLiteral("Position (mm)"),
        QStringLiteral("Error [µm]"),    QStringLiteral("Time [s]"),
        QStringLiteral("Air temp [°C]"), QStringLiteral("Air pressure [hPa]")};
    using interferometer::guessColumn;
    using interferometer::ReadingRole;
    EXPECT_EQ(guessColumn(ReadingRole::Time, header), 3);
    EXPECT_EQ(guessColumn(ReadingRole::Position, header), 1);
    EXPECT_EQ(guessColumn(ReadingRole::Deviation, header), 2);
    EXPECT_EQ(guessColumn(ReadingRole::Air, header), 4);
    EXPECT_EQ(guessColumn(ReadingRole::Pressure, header), 5);
    EXPECT_EQ(guessColumn(ReadingRole::Humidity, header), std::nullopt);
}
