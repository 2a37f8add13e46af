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

/// The correlation of `drift` with `room` delayed by `shift` samples.
double delayedCorrelation(const std::vector<double>& drift, const std::vector<double>& room,
                          std::size_t shift) {
    return correlation(std::vector<double>(drift.begin() + std::ptrdiff_t(shift), drift.end()),
                       std::vector<double>(room.begin(), room.end() - std::ptrdiff_t(shift)));
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
    // The structure follows the room, hours late (the column core's time
    // constant): a warmer room, a longer spindle, the tool further towards the
    // work (negative z). The best match is the room of some hours before.
    std::size_t bestShift = 0;
    for (std::size_t shift = 0; shift <= 4 * 60; shift += 5)  // samples are a minute apart
        if (delayedCorrelation(driftZ, ambient, shift) <
            delayedCorrelation(driftZ, ambient, bestShift))
            bestShift = shift;
    EXPECT_LT(delayedCorrelation(driftZ, ambient, bestShift), -0.9);
    EXPECT_GE(bestShift, 60u) << "the drift lags the room by an hour or more";
    EXPECT_GT(correlation(driftZ, ambient), delayedCorrelation(driftZ, ambient, bestShift));
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
    // Printed by the simulator when the head became a thermal network (issue 10).
    EXPECT_DOUBLE_EQ(driftZ[720], -11.962);
    EXPECT_DOUBLE_EQ(column(run, "T_spindle")[1500], 24.11);
    EXPECT_DOUBLE_EQ(column(run, "T_ambient")[1980], 20.01);
    double sumZ_um = 0, sumSpindle_C = 0;
    for (double v : driftZ) sumZ_um += v;
    for (double v : column(run, "T_spindle")) sumSpindle_C += v;
    EXPECT_NEAR(sumZ_um, -25509.84, 1e-6);
    EXPECT_NEAR(sumSpindle_C, 46763.24, 1e-6);
}
