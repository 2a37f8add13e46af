// Building and checking a table: the sign convention, interpolation without
// extrapolation, and every limit refused with the point and value named.

#include <gtest/gtest.h>

#include "core/compensation/CsvExport.h"
#include "core/compensation/FanucExport.h"
#include "core/compensation/SinumerikExport.h"
#include "tests/compensation/CompensationTestData.h"

namespace driftlab::compensation {
namespace {

using driftlab::Direction;
using iso::Reading;
using test::handTable;

/// Two cycles, both directions, the same deviation everywhere but `at_mm`.
std::vector<Reading> readings(double at_mm, double deviation_um) {
    std::vector<Reading> r;
    for (int cycle = 1; cycle <= 2; ++cycle)
        for (double target : {0.0, 100.0, 200.0})
            for (Direction d : {Direction::Positive, Direction::Negative})
                r.push_back({target, d, cycle, target == at_mm ? deviation_um : 0.0});
    return r;
}

TableResult build(const std::vector<Reading>& r, TableSettings settings, Limits limits = {}) {
    return buildTable(iso::evaluate(r), settings, limits);
}

// The worked example of docs/compensation.md: the laser reads +3 µm at 100 mm
// (the axis stops 3 µm beyond the target), so the controller must command
// 3 µm less there: correction −3 µm.
TEST(CompensationTable, deviationPlusThreeGivesCorrectionMinusThree) {
    TableSettings s;
    s.points = 3;
    const TableResult r = build(readings(100, 3), s);
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    EXPECT_DOUBLE_EQ(r.table.position_mm[1], 100);
    EXPECT_DOUBLE_EQ(r.table.meanCorrectionUm(1), -3);
    EXPECT_DOUBLE_EQ(r.table.meanCorrectionUm(0), 0);
    // Sinumerik corrects the actual value: it holds +deviation, +0.003 mm.
    EXPECT_TRUE(exportSinumerik(r.table, {}).text.contains("$AA_ENC_COMP[0,1,AX1]=0.0030\n"));
}

TEST(CompensationTable, valuesBetweenTargetsAreInterpolatedLinearly) {
    TableSettings s;
    s.spacing_mm = 25;
    const TableResult r = build(readings(100, 4), s);
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    ASSERT_EQ(r.table.size(), 9u);
    EXPECT_DOUBLE_EQ(r.table.meanCorrectionUm(3), -3);  // 75 mm: ¾ of the way to −4
    EXPECT_DOUBLE_EQ(r.table.meanCorrectionUm(5), -3);  // 125 mm
}

TEST(CompensationTable, rangeBeyondTheMeasuredTargetsIsRefused) {
    TableSettings s;
    s.spacing_mm = 10;
    s.end_mm = 210;
    const TableResult r = build(readings(100, 3), s);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(
        r.error.contains(QStringLiteral("0.000 to 210.000 mm reaches beyond the measured "
                                        "targets 0.000 to 200.000 mm")))
        << qPrintable(r.error);
}

TEST(CompensationTable, spacingThatDoesNotDivideTheRangeWarnsWhereTheTableEnds) {
    TableSettings s;
    s.spacing_mm = 30;
    const TableResult r = build(readings(100, 3), s);
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    EXPECT_EQ(r.table.size(), 7u);
    ASSERT_EQ(r.warnings.size(), 1);
    EXPECT_TRUE(r.warnings.front().contains(QStringLiteral("ends at 180.000 mm")));
}

TEST(CompensationTable, valueBeyondTheLimitNamesPointAndValue) {
    TableSettings s;
    s.points = 3;
    Limits limits;
    limits.max_value_um = 2.5;
    const TableResult r = build(readings(100, 3), s, limits);
    EXPECT_EQ(r.error, QStringLiteral("point 1 at 100.000 mm: correction -3.000 µm exceeds the "
                                      "limit ±2.500 µm (max value)"));
}

TEST(CompensationTable, stepBeyondTheLimitNamesBothPoints) {
    TableSettings s;
    s.points = 3;
    Limits limits;
    limits.max_step_um = 2;
    const TableResult r = build(readings(100, 3), s, limits);
    EXPECT_EQ(r.error, QStringLiteral("point 1 at 100.000 mm: correction steps from 0.000 µm to "
                                      "-3.000 µm (-3.000 µm) against point 0, beyond the limit "
                                      "2.000 µm between neighbours (max step)"));
}

TEST(CompensationTable, changeAgainstThePreviousTableIsLimited) {
    Limits limits;
    limits.max_change_um = 1;
    const CompensationTable before = handTable({0, 10, 20}, {0, 1, 2});
    const CompensationTable after = handTable({0, 10, 20}, {0, 1.5, 3.5});
    EXPECT_EQ(checkChange(before, after, limits),
              QStringLiteral("point 2 at 20.000 mm: correction changes from 2.000 µm to 3.500 µm, "
                             "beyond the limit 1.000 µm per update (max change)"));
    EXPECT_EQ(checkChange(before, handTable({0, 10, 20}, {0.5, 1.5, 2.5}), limits), QString());
}

TEST(CompensationTable, malformedTablesAreRefused) {
    const Limits limits;
    EXPECT_TRUE(validate(handTable({0, 10, 10}, {0, 0, 0}), limits, 100)
                    .startsWith(QStringLiteral("point 2 at 10.000 mm: positions must increase")));
    EXPECT_TRUE(
        validate(handTable({0, 10, 20}, {0, std::nan(""), 0}), limits, 100)
            .startsWith(QStringLiteral("point 1 at 10.000 mm: correction is not a finite")));
    EXPECT_EQ(validate(handTable({0, 10, 20}, {0, 0, 0}), limits, 2),
              QStringLiteral("3 points exceed the maximum of 2"));
}

TEST(CompensationTable, aTargetMeasuredFromOneSideOnlyIsRefused) {
    std::vector<Reading> r;
    for (double target : {0.0, 100.0}) r.push_back({target, Direction::Positive, 1, 1.0});
    EXPECT_EQ(build(r, {}).error, QStringLiteral("target 0 mm, direction - (↓): no reading; ISO "
                                                 "230-2 needs both approaches at every target"));
}

// The thermal part: an extra error profile (a model's error at a stated
// state) adds to the cold deviation before the sign is turned.
TEST(CompensationTable, extraErrorProfileAddsToTheColdError) {
    TableSettings s;
    s.points = 3;
    const TableResult r =
        buildTable(iso::evaluate(readings(100, 3)), s, {}, [](double x_mm) { return x_mm / 100; });
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    EXPECT_DOUBLE_EQ(r.table.meanCorrectionUm(1), -4);
    EXPECT_DOUBLE_EQ(r.table.meanCorrectionUm(2), -2);
}

TEST(CompensationTable, fanucIncrementBeyondThePerPointLimitIsNamed) {
    const ExportResult r =
        exportFanucParameters(handTable({0, 10, 20}, {0, 9, 9}), FanucSettings{});
    EXPECT_EQ(r.error, QStringLiteral("Fanuc point number 1 (0.000 to 10.000 mm): increment 9 × 1 "
                                      "µm exceeds the per-point limit ±7 (magnification 1): use "
                                      "a finer spacing or a larger magnification"));
    FanucSettings coarse;
    coarse.magnification = 2;
    EXPECT_TRUE(exportFanucParameters(handTable({0, 10, 20}, {0, 9, 9}), coarse).ok());
}

TEST(CompensationTable, csvHasNoNegativeZero) {
    const QByteArray text = exportCsv(handTable({0, 1}, {-0.0001, 0})).text;
    EXPECT_EQ(text, QByteArray("position_mm,correction_um\n0.0000,0.000\n1.0000,0.000\n"));
}

}  // namespace
}  // namespace driftlab::compensation
