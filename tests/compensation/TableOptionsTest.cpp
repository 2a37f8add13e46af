// The table options controllers ask for, worked on the hand-checked table
// (CompensationTestData.h: corrections −x̄ = −0.5, −2.0, −3.5, −0.5, 2.5 µm
// every 50 mm; bidirectional + −3, −3.5, −4, −1.5, 1 and − 2, −0.5, −3, 0.5,
// 4 µm): the sign, absolute or incremental values, per direction, the
// resampling and the warning on targets at one phase of the screw lead.

#include <gtest/gtest.h>

#include "core/compensation/CsvExport.h"
#include "core/compensation/FanucExport.h"
#include "core/compensation/FormatOptions.h"
#include "core/compensation/HeidenhainExport.h"
#include "core/compensation/LeadAliasing.h"
#include "core/compensation/LinuxCncExport.h"
#include "core/compensation/SinumerikExport.h"
#include "core/compensation/TableExport.h"
#include "tests/compensation/CompensationTestData.h"

namespace driftlab::compensation {
namespace {

using test::golden50mm;

CompensationTable goldenTable(bool bidirectional, std::optional<ValueSign> sign = {},
                              std::optional<ValueMode> mode = {}) {
    TableResult r = golden50mm(bidirectional);
    EXPECT_TRUE(r.ok()) << qPrintable(r.error);
    r.table.sign = sign;
    r.table.values = mode;
    return r.table;
}

// Error = +deviation: the correction's opposite, x̄ = 0.5, 2, 3.5, 0.5, −2.5.
TEST(TableOptions, signErrorWritesTheDeviationInTheCsv) {
    const ExportResult r = exportCsv(goldenTable(false, ValueSign::Error));
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    EXPECT_EQ(r.text, QByteArray("position_mm,error_um,uncertainty_um\n"
                                 "0.0000,0.500,0.632\n50.0000,2.000,0.670\n"
                                 "100.0000,3.500,0.707\n150.0000,0.500,0.577\n"
                                 "200.0000,-2.500,0.447\n"));
}

// Incremental: −0.5 − 0 = −0.5, −2 − (−0.5) = −1.5, −3.5 − (−2) = −1.5,
// −0.5 − (−3.5) = 3, 2.5 − (−0.5) = 3; their running sum is the table.
TEST(TableOptions, incrementalValuesAreTheChangeFromThePreviousPoint) {
    const ExportResult r = exportCsv(goldenTable(false, {}, ValueMode::Incremental));
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    EXPECT_EQ(r.text, QByteArray("position_mm,correction_increment_um,uncertainty_um\n"
                                 "0.0000,-0.500,0.632\n50.0000,-1.500,0.670\n"
                                 "100.0000,-1.500,0.707\n150.0000,3.000,0.577\n"
                                 "200.0000,3.000,0.447\n"));
}

// Per direction, error sign, incremental: + errors 3, 3.5, 4, 1.5, −1 give
// 3, 0.5, 0.5, −2.5, −2.5; − errors −2, 0.5, 3, −0.5, −4 give −2, 2.5, 2.5,
// −3.5, −3.5.
TEST(TableOptions, bidirectionalErrorIncrementsHaveOneColumnPerDirection) {
    const ExportResult r = exportCsv(goldenTable(true, ValueSign::Error, ValueMode::Incremental));
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    EXPECT_EQ(r.text,
              QByteArray("position_mm,error_increment_um,error_increment_minus_um,uncertainty_um\n"
                         "0.0000,3.000,-2.000,0.894\n50.0000,0.500,2.500,1.118\n"
                         "100.0000,0.500,2.500,1.342\n150.0000,-2.500,-3.500,1.118\n"
                         "200.0000,-2.500,-3.500,0.894\n"));
}

// Heidenhain holds either sign: with the error the axis column is +x̄↑ and
// BACKLASH the − error minus the + error (at 0 mm: −2 − 3 = −5 µm).
TEST(TableOptions, heidenhainWithSignErrorHoldsTheDeviation) {
    const ExportResult r = exportHeidenhain(goldenTable(true, ValueSign::Error), {});
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    EXPECT_TRUE(r.text.contains("0     +0.0000         +0.0030         -0.0050\n"))
        << r.text.constData();
    EXPECT_TRUE(r.text.contains("4     +200.0000       -0.0010         -0.0030\n"))
        << r.text.constData();
}

// Each controller's own convention is the default, and asking for it
// explicitly writes the same bytes.
TEST(TableOptions, theFormatsOwnConventionIsTheDefault) {
    EXPECT_EQ(effectiveSign(QStringLiteral("linuxcnc"), {}), ValueSign::Error);
    EXPECT_EQ(effectiveSign(QStringLiteral("linuxcnc-type1"), {}), ValueSign::Correction);
    EXPECT_EQ(effectiveSign(QStringLiteral("sinumerik"), {}), ValueSign::Error);
    EXPECT_EQ(effectiveSign(QStringLiteral("fanuc"), {}), ValueSign::Correction);
    EXPECT_EQ(effectiveMode(QStringLiteral("fanuc"), {}), ValueMode::Incremental);
    EXPECT_EQ(effectiveSign(QStringLiteral("csv"), {}), ValueSign::Correction);
    EXPECT_EQ(effectiveMode(QStringLiteral("csv"), {}), ValueMode::Absolute);
    const CompensationTable plain = goldenTable(false);
    EXPECT_EQ(exportLinuxCnc(goldenTable(false, ValueSign::Error), LinuxCncType::Type0).text,
              exportLinuxCnc(plain, LinuxCncType::Type0).text);
    EXPECT_EQ(exportSinumerik(goldenTable(false, ValueSign::Error), {}).text,
              exportSinumerik(plain, {}).text);
    const ExportResult fanuc = exportFanucParameters(
        goldenTable(false, ValueSign::Correction, ValueMode::Incremental), {});
    ASSERT_TRUE(fanuc.ok()) << qPrintable(fanuc.error);
    EXPECT_EQ(fanuc.text, exportFanucParameters(plain, {}).text);
}

TEST(TableOptions, anOptionTheFormatCannotHoldIsRefusedSayingWhy) {
    EXPECT_EQ(checkFormatOptions(QStringLiteral("sinumerik"), ValueSign::Correction, {}, false),
              QStringLiteral("--sign correction: sinumerik holds the error only: Sinumerik "
                             "corrects the actual value: a positive compensation value moves "
                             "the axis in the negative direction"));
    EXPECT_TRUE(checkFormatOptions(QStringLiteral("fanuc"), {}, ValueMode::Absolute, false)
                    .startsWith(QStringLiteral("--values absolute: fanuc holds incremental "
                                               "values only")));
    EXPECT_TRUE(checkFormatOptions(QStringLiteral("linuxcnc"), {}, ValueMode::Incremental, false)
                    .startsWith(QStringLiteral("--values incremental: linuxcnc holds absolute")));
    EXPECT_TRUE(checkFormatOptions(QStringLiteral("fanuc-g10"), {}, {}, true)
                    .startsWith(QStringLiteral("--bidirectional: fanuc-g10 holds one combined "
                                               "table only")));
    for (const QString& format : {QStringLiteral("csv"), QStringLiteral("heidenhain")})
        for (ValueSign sign : {ValueSign::Correction, ValueSign::Error})
            EXPECT_EQ(checkFormatOptions(format, sign, {}, true), QString()) << qPrintable(format);
    // The exporter refuses it too: a type 0 file cannot hold corrections, a
    // type 1 file cannot hold errors. Flipping silently would double the error.
    const ExportResult type0 =
        exportLinuxCnc(goldenTable(false, ValueSign::Correction), LinuxCncType::Type0);
    EXPECT_TRUE(
        type0.error.startsWith(QStringLiteral("--sign correction: linuxcnc holds the "
                                              "error only: COMP_FILE_TYPE 0")))
        << qPrintable(type0.error);
    EXPECT_FALSE(exportLinuxCnc(goldenTable(false, ValueSign::Error), LinuxCncType::Type1).ok());
    EXPECT_FALSE(exportFanucG10(goldenTable(false, {}, ValueMode::Absolute), {}).ok());
    EXPECT_FALSE(
        exportTable(goldenTable(false, {}, ValueMode::Incremental), "heidenhain", {}).ok());
}

// Per direction where the format holds it: LinuxCNC type 1 writes −x̄↑ and
// −x̄↓ as they are (0 mm: −3 and +2 µm).
TEST(TableOptions, perDirectionColumnsReachTheLinuxCncTrims) {
    const ExportResult r = exportLinuxCnc(goldenTable(true), LinuxCncType::Type1);
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    EXPECT_TRUE(r.text.startsWith("0.0000 -0.0030 0.0020\n")) << r.text.constData();
}

// Resampled to a controller's spacing of 25 mm: at 25 mm halfway from −0.5
// to −2.0, −1.25 µm; at 175 mm halfway from −0.5 to 2.5, 1.0 µm.
TEST(TableOptions, resampledToAFixedSpacingBetweenTheTargets) {
    TableSettings s;
    s.spacing_mm = 25;
    const TableResult r = buildTable(iso::evaluate(iso::test::golden3x5()), s);
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    ASSERT_EQ(r.table.size(), 9u);
    EXPECT_NEAR(r.table.meanCorrectionUm(1), -1.25, 1e-12);
    EXPECT_NEAR(r.table.meanCorrectionUm(7), 1.0, 1e-12);
}

// The golden targets 0, 100, 200 mm are whole multiples of a 10 mm lead (and
// of 5 mm, 20 mm...): one phase of the screw's periodic error. With a 7 mm
// lead 100/7 is not whole: no warning.
TEST(TableOptions, targetsOnMultiplesOfTheScrewLeadWarn) {
    TableSettings s;
    s.spacing_mm = 50;
    s.screw_lead_mm = 10;
    const TableResult on = buildTable(iso::evaluate(iso::test::golden3x5()), s);
    ASSERT_TRUE(on.ok()) << qPrintable(on.error);
    ASSERT_EQ(on.warnings.size(), 1);
    EXPECT_TRUE(on.warnings.front().startsWith(
        QStringLiteral("the 3 measured targets (0.000 to 200.000 mm) all lie 0.000 mm past a "
                       "multiple of the 10.000 mm screw lead")))
        << qPrintable(on.warnings.front());
    s.screw_lead_mm = 7;
    EXPECT_TRUE(buildTable(iso::evaluate(iso::test::golden3x5()), s).warnings.isEmpty());
    s.screw_lead_mm = 0;  // unknown lead
    EXPECT_TRUE(buildTable(iso::evaluate(iso::test::golden3x5()), s).warnings.isEmpty());
    // The same phase off zero aliases as much: 3, 13, 43 mm with a 5 mm lead.
    EXPECT_TRUE(leadAliasingWarning({3, 13, 43}, 5).contains(QStringLiteral("all lie 3.000 mm")));
    // ISO 230-2's irregular spacing: one target off the phase is enough.
    EXPECT_EQ(leadAliasingWarning({0, 103.7, 200}, 10), QString());
}

}  // namespace
}  // namespace driftlab::compensation
