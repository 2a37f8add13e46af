// The spindle simulator as an ETVE rig: at rest, the probes drift with the room.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/procedures/ProcedurePlan.h"
#include "core/rig/SpindleTestSimulator.h"
#include "tests/procedures/ProcedureTestSupport.h"

using namespace driftlab;
using namespace driftlab::procedures;

namespace {

std::vector<QString> spindleColumns() {
    std::vector<QString> columns;
    for (const Channel& c : rig::spindleTestChannels()) columns.push_back(c.id);
    columns.push_back(QStringLiteral("T_ambient"));
    return columns;
}

const std::vector<double>& column(const Run& run, const char* id) {
    return run.samples.values[std::size_t(run.samples.columnIndex(QString::fromLatin1(id)))];
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    const double n = double(a.size());
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) ma += a[i] / n, mb += b[i] / n;
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return sab / std::sqrt(saa * sbb);
}

double peakToPeak(const std::vector<double>& v) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return *hi - *lo;
}

rig::SpindleTestSpec plannedEtve() {
    const std::vector<PlannedRun> runs = planRuns(test::shipped("etve-8h.json"));
    EXPECT_EQ(runs.size(), 1u);
    EXPECT_TRUE(runs.front().spindle);
    return *runs.front().spindle;
}

}  // namespace

TEST(EtveSimulator, aMachineAtRestDriftsWithTheRoom) {
    rig::SpindleTestSpec spec = plannedEtve();
    spec.ambient_swing_K = 1.0;
    const driftlab::Run run = rig::simulateSpindleTest(spec, spindleColumns());
    EXPECT_EQ(run.kind, RunKind::Etve);
    EXPECT_EQ(run.id, QStringLiteral("E1"));
    EXPECT_EQ(run.samples.rowCount(), 28800u / 60 + 1);
    const auto& ambient = column(run, "T_ambient");
    const auto& driftZ = column(run, "D_z");
    EXPECT_GT(peakToPeak(ambient), 1.5);  // ±1 K over 8 h of a 12 h period
    EXPECT_GT(peakToPeak(driftZ), 3.0);
    // The structure lags the room but follows it: a warmer room, a longer
    // spindle, the tool further towards the work (negative z).
    EXPECT_LT(correlation(driftZ, ambient), -0.8);
    for (double speed : column(run, "S_speed")) EXPECT_EQ(speed, 0);
}

TEST(EtveSimulator, withoutASwingTheMachineAtRestDoesNotDrift) {
    const driftlab::Run run = rig::simulateSpindleTest(plannedEtve(), spindleColumns());
    EXPECT_LT(peakToPeak(column(run, "D_z")), 1.0);  // probe noise only (0.1 µm)
    EXPECT_LT(peakToPeak(column(run, "T_ambient")), 0.5);
}

TEST(EtveSimulator, withoutASwingTheSpindleTestIsUnchanged) {
    // Values of the default spindle test before the room could swing: the
    // swing adds exactly nothing when it is 0, whatever its period.
    rig::SpindleTestSpec spec;
    spec.ambient_period_s = 1000;
    const driftlab::Run run = rig::simulateSpindleTest(spec, spindleColumns());
    const driftlab::Run reference = rig::simulateSpindleTest({}, spindleColumns());
    EXPECT_EQ(run.samples, reference.samples);
    EXPECT_EQ(run.kind, RunKind::Spindle);
    const auto& driftZ = column(run, "D_z");
    ASSERT_EQ(driftZ.size(), 1981u);
    // Printed by the simulator as it was before ambient_swing_K existed.
    EXPECT_DOUBLE_EQ(driftZ[720], -11.537);
    EXPECT_DOUBLE_EQ(column(run, "T_spindle")[1500], 22.81);
    EXPECT_DOUBLE_EQ(column(run, "T_ambient")[1980], 20.01);
    double sumZ_um = 0, sumSpindle_C = 0;
    for (double v : driftZ) sumZ_um += v;
    for (double v : column(run, "T_spindle")) sumSpindle_C += v;
    EXPECT_NEAR(sumZ_um, -16778.972, 1e-6);
    EXPECT_NEAR(sumSpindle_C, 47327.93, 1e-6);
}
