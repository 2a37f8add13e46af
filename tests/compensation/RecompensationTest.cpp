// Re-compensation: the residual measured with a table switched on is added
// to it, the change per point is the residual's correction, the limits hold
// for the sum, and an active table is read back from the controller's own
// file or DriftLab's CSV.

#include <gtest/gtest.h>

#include <QFile>

#include "core/compensation/ActiveTableRead.h"
#include "core/compensation/CsvExport.h"
#include "core/compensation/HeidenhainExport.h"
#include "core/compensation/Recompensation.h"
#include "tests/compensation/CompensationTestData.h"

namespace driftlab::compensation {
namespace {

using test::golden50mm;
using test::handTable;

QByteArray goldenText(const char* name) {
    QFile file(QStringLiteral(DRIFTLAB_SOURCE_DIR "/tests/compensation/golden/") +
               QLatin1String(name));
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << name;
    return file.readAll();
}

CompensationTable residual(bool bidirectional) {
    const TableResult r = golden50mm(bidirectional);
    EXPECT_TRUE(r.ok()) << qPrintable(r.error);
    return r.table;
}

// Active −1, −2, −3 µm at 0, 100, 200 mm (−1.5 and −2.5 between); residual
// corrections −0.5, −2, −3.5, −0.5, 2.5: new −1.5, −3.5, −5.5, −3, −0.5.
TEST(Recompensation, theResidualsCorrectionIsAddedToTheActiveTable) {
    const RecompensationResult r =
        recompensate(handTable({0, 100, 200}, {-1, -2, -3}), residual(false), {}, 1024);
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    const double expected[] = {-1.5, -3.5, -5.5, -3.0, -0.5};
    const double old[] = {-1, -1.5, -2, -2.5, -3};
    const double change[] = {-0.5, -2, -3.5, -0.5, 2.5};
    ASSERT_EQ(r.changes.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_NEAR(r.table.meanCorrectionUm(i), expected[i], 1e-12) << i;
        EXPECT_NEAR(r.changes[i].old_plus_um, old[i], 1e-12) << i;
        EXPECT_NEAR(r.changes[i].changePlusUm(), change[i], 1e-12) << i;
    }
    EXPECT_NEAR(r.table.mean_reversal_um, 3, 1e-12);  // the residual's, the active had none
}

// A LinuxCNC table folds B̄ into its columns: − minus + = 3 µm in the active
// table plus the residual's 3 µm gives B̄ = 6 µm; the mean is as above.
TEST(Recompensation, theReversalTheActiveColumnsHeldIsKept) {
    CompensationTable active = handTable({0, 100, 200}, {-1, -2, -3});
    for (double& v : active.correction_plus_um) v -= 1.5;
    for (double& v : active.correction_minus_um) v += 1.5;
    const RecompensationResult r = recompensate(active, residual(false), {}, 1024);
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    EXPECT_NEAR(r.table.meanCorrectionUm(2), -5.5, 1e-12);
    EXPECT_NEAR(r.table.mean_reversal_um, 6, 1e-12);
    EXPECT_TRUE(r.warnings.isEmpty());
}

// Per direction: active + −1, −2, −3 and − 1, 0, −1; at 50 mm + −1.5 and
// − 0.5, plus the residual's −3.5 and −0.5: −5 and 0.
TEST(Recompensation, perDirectionEachColumnGetsItsOwnResidual) {
    CompensationTable active = handTable({0, 100, 200}, {-1, -2, -3});
    active.correction_minus_um = {1, 0, -1};
    active.bidirectional = true;
    const RecompensationResult r = recompensate(active, residual(true), {}, 1024);
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    EXPECT_NEAR(r.table.correction_plus_um[1], -5, 1e-12);
    EXPECT_NEAR(r.table.correction_minus_um[1], 0, 1e-12);
    EXPECT_NEAR(r.changes[1].changeMinusUm(), -0.5, 1e-12);
}

TEST(Recompensation, theLimitsHoldForTheSum) {
    Limits limits;
    limits.max_value_um = 5;
    const RecompensationResult r =
        recompensate(handTable({0, 100, 200}, {-1, -2, -3}), residual(false), limits, 1024);
    EXPECT_EQ(r.error, QStringLiteral("point 2 at 100.000 mm: correction -5.500 µm exceeds the "
                                      "limit ±5.000 µm (max value)"));
    limits = {};
    limits.max_step_um = 2;
    EXPECT_TRUE(recompensate(handTable({0, 100, 200}, {-1, -2, -3}), residual(false), limits, 1024)
                    .error.contains(QStringLiteral("(max step)")));
}

// The golden LinuxCNC type 0 file (B̄ = 3 µm folded): its first row
// 0.0000 0.0020 -0.0010 is trim + −2 µm and trim − +1 µm, mean −0.5 µm.
TEST(ActiveTableRead, aLinuxCncType0FileReadsBackAsTrims) {
    const ActiveTableRead r = readActiveTable(goldenText("linuxcnc_type0.comp"),
                                              QStringLiteral("linuxcnc"), {}, "x.comp");
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    ASSERT_EQ(r.table.size(), 5u);
    EXPECT_NEAR(r.table.correction_plus_um[0], -2, 1e-9);
    EXPECT_NEAR(r.table.correction_minus_um[0], 1, 1e-9);
    EXPECT_NEAR(r.table.meanCorrectionUm(4), 2.5, 1e-9);
}

TEST(ActiveTableRead, sinumerikHoldsTheErrorAndReadsBackAsCorrections) {
    const ActiveTableRead r =
        readActiveTable(goldenText("sinumerik_eec.ini"), QStringLiteral("sinumerik"), {}, "x.ini");
    ASSERT_TRUE(r.ok()) << qPrintable(r.error);
    ASSERT_EQ(r.table.size(), 5u);
    EXPECT_DOUBLE_EQ(r.table.position_mm[3], 150);
    EXPECT_NEAR(r.table.meanCorrectionUm(2), -3.5, 1e-9);
}

// Whatever sign and mode DriftLab wrote, reading it back gives the table.
TEST(ActiveTableRead, csvAndHeidenhainRoundTripInEverySign) {
    for (ValueSign sign : {ValueSign::Correction, ValueSign::Error})
        for (ValueMode mode : {ValueMode::Absolute, ValueMode::Incremental}) {
            CompensationTable table = residual(true);
            table.sign = sign;
            table.values = mode;
            const ActiveTableRead csv = readActiveTable(exportCsv(table).text, {}, {}, "t.csv");
            ASSERT_TRUE(csv.ok()) << qPrintable(csv.error);
            for (std::size_t i = 0; i < 5; ++i) {
                EXPECT_NEAR(csv.table.correction_plus_um[i], table.correction_plus_um[i], 1e-9);
                EXPECT_NEAR(csv.table.correction_minus_um[i], table.correction_minus_um[i], 1e-9);
            }
            if (mode == ValueMode::Incremental) continue;
            const ActiveTableRead com = readActiveTable(
                exportHeidenhain(table, {}).text, QStringLiteral("heidenhain"), sign, "X.COM");
            ASSERT_TRUE(com.ok()) << qPrintable(com.error);
            EXPECT_NEAR(com.table.correction_minus_um[0], 2, 1e-9);
            EXPECT_NEAR(com.table.correction_plus_um[4], 1, 1e-9);
        }
}

TEST(ActiveTableRead, aFileThatWouldTruncateOrCannotBeReadIsRefused) {
    EXPECT_EQ(
        readActiveTable("0 0 0\n# comment\n10 10 10\n", QStringLiteral("linuxcnc"), {}, "x.comp")
            .error,
        QStringLiteral("x.comp:2: '# comment' is not 'nominal second third' (LinuxCNC "
                       "would stop reading the table here)"));
    EXPECT_TRUE(readActiveTable(goldenText("fanuc.prm"), QStringLiteral("fanuc"), {}, "f.prm")
                    .error.startsWith(QStringLiteral("f.prm: a fanuc table cannot be read back")));
    EXPECT_TRUE(readActiveTable("position_mm,correction_um\n0,1\n0,2\n", {}, {}, "t.csv")
                    .error.startsWith(QStringLiteral("t.csv: point 1 at 0.000 mm: positions must "
                                                     "increase")));
}

}  // namespace
}  // namespace driftlab::compensation
