// Import of an interferometer CSV export in the generic layout.
#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>

#include "core/interferometer/InterferometerCsvImport.h"

using namespace driftlab;

namespace {

QString writeCsv(const QTemporaryDir& dir, const QByteArray& text) {
    const QString path = dir.filePath(QStringLiteral("export.csv"));
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(text);
    return path;
}

interferometer::InterferometerHeader off() {
    interferometer::InterferometerHeader h;
    h.compensationOn = false;
    h.assumedIndex = 1.0;
    return h;
}

}  // namespace

TEST(InterferometerCsvImport, correctsEachRowWithTheAirOfItsRowOrTheRowBefore) {
    QTemporaryDir dir;
    // Columns in another order, an extra column, the air logged every other row.
    const QString path = writeCsv(dir,
                                  "position_mm,time_s,deviation_um,note,air_C,pressure_Pa,"
                                  "humidity_pct\n"
                                  "0,0,0,start,20.5,101000,40\n"
                                  "100,1,1.5,,,,\n"
                                  "200,2,3,,21.5,100500,45\n");
    const interferometer::InterferometerCsvImport imported =
        interferometer::importInterferometerCsv(path, off());
    ASSERT_FALSE(imported.error) << imported.error->toString().toStdString();
    ASSERT_EQ(imported.readings.size(), 3u);
    const double n1 =
        interferometer::edlenRefractiveIndex(interferometer::AirState{20.5, 101'000, 40});
    const double n2 =
        interferometer::edlenRefractiveIndex(interferometer::AirState{21.5, 100'500, 45});
    EXPECT_EQ(imported.readings[1].line, 3);
    EXPECT_NEAR(imported.readings[1].position_mm, 100.0 / n1, 1e-12);
    EXPECT_NEAR(imported.readings[1].deviation_um, 1.5 + 100.0 * 1000 * (1 / n1 - 1), 1e-7);
    EXPECT_NEAR(imported.readings[2].position_mm, 200.0 / n2, 1e-12);
    EXPECT_TRUE(imported.correction.startsWith(QStringLiteral("Edlén, 21.5 °C, 100.5 kPa, 45 %RH")))
        << imported.correction.toStdString();
}

TEST(InterferometerCsvImport, columnsAsAVendorSpellsThemWithTheirUnitsAreTheLayoutsOwn) {
    // Capitalised, units in brackets: "Air [°C]" is air_C, "Humidity [%]" is
    // humidity_pct; the readings are those of the generic spelling.
    QTemporaryDir dir;
    const QByteArray rows = "0,0,0,20.5,101000,40\n100,1,1.5,21.5,100500,45\n";
    const QString plain =
        writeCsv(dir, "position_mm,time_s,deviation_um,air_C,pressure_Pa,humidity_pct\n" + rows);
    const interferometer::InterferometerCsvImport expected =
        interferometer::importInterferometerCsv(plain, off());
    const QString spelled = writeCsv(dir,
                                     "Position [mm],Time (s),Deviation [\xC2\xB5m],Air [\xC2\xB0"
                                     "C],Pressure [Pa],Humidity [%]\n" +
                                         rows);
    const interferometer::InterferometerCsvImport imported =
        interferometer::importInterferometerCsv(spelled, off());
    ASSERT_FALSE(imported.error) << imported.error->toString().toStdString();
    ASSERT_EQ(imported.readings.size(), 2u);
    EXPECT_EQ(imported.readings[1].deviation_um, expected.readings[1].deviation_um);
    EXPECT_EQ(imported.readings[1].position_mm, expected.readings[1].position_mm);
    EXPECT_EQ(imported.correction, expected.correction);
    EXPECT_NE(imported.readings[1].deviation_um, 1.5);  // the air was read and corrected for
}

TEST(InterferometerCsvImport, compensatedExportNeedsNoAir) {
    QTemporaryDir dir;
    const QString path = writeCsv(dir, "time_s,position_mm,deviation_um\n0,0,0\n1,100,1.5\n");
    const interferometer::InterferometerCsvImport imported =
        interferometer::importInterferometerCsv(path, interferometer::InterferometerHeader{});
    ASSERT_FALSE(imported.error) << imported.error->toString().toStdString();
    ASSERT_EQ(imported.readings.size(), 2u);
    EXPECT_EQ(imported.readings[1].deviation_um, 1.5);
    EXPECT_EQ(imported.correction, QStringLiteral("none: the interferometer compensated itself"));
}

TEST(InterferometerCsvImport, errorsNameFileLineAndColumnAndKeepTheRowsBefore) {
    QTemporaryDir dir;
    const QString hpa = writeCsv(dir,
                                 "time_s,position_mm,deviation_um,air_C,pressure_Pa,humidity_pct\n"
                                 "0,0,0,20,101325,50\n"
                                 "1,100,1,20,1013.25,50\n");
    const interferometer::InterferometerCsvImport a =
        interferometer::importInterferometerCsv(hpa, off());
    ASSERT_TRUE(a.error);
    EXPECT_EQ(a.error->toString(),
              QStringLiteral("export.csv:3:5: air pressure 1013.25 Pa is outside 60000…120000 Pa "
                             "(hPa? DriftLab expects Pa)"));
    EXPECT_EQ(a.readings.size(), 1u);

    const QString noAir = writeCsv(dir, "time_s,position_mm,deviation_um\n0,0,0\n");
    const interferometer::InterferometerCsvImport b =
        interferometer::importInterferometerCsv(noAir, off());
    ASSERT_TRUE(b.error);
    EXPECT_EQ(b.error->toString(),
              QStringLiteral("export.csv:1: the interferometer's compensation was off but the "
                             "file has no air_C, pressure_Pa and humidity_pct columns to correct "
                             "it with"));

    const QString micrometres = writeCsv(dir, "time_s,position_mm,deviation_um\n0,150000,0\n");
    const interferometer::InterferometerCsvImport c = interferometer::importInterferometerCsv(
        micrometres, interferometer::InterferometerHeader{});
    ASSERT_TRUE(c.error);
    EXPECT_EQ(c.error->toString(),
              QStringLiteral("export.csv:2:2: 150000 mm is beyond ±100000 mm (µm instead of mm?)"));
}
