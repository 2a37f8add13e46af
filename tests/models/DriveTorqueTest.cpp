// The motor heat's input, the mean of τ² over each step of the screw
// simulation, from a drive's torque log and the axis motion.
#include <gtest/gtest.h>

#include <cmath>

#include "core/models/DriveTorque.h"

using namespace driftlab;
using namespace driftlab::models;

namespace {

constexpr double kLead_mm = 10, kSpeed_mm_s = 100, kCoulomb_Nm = 0.8, kViscous_Nm_s = 0.002;

/// Back and forth at 100 mm/s, reversing every 5 s, for 600 s.
RunData reversingRun() {
    RunData run;
    run.run_id = QStringLiteral("R1");
    Screw screw;
    screw.length_mm = 800;
    screw.diameter_mm = 32;
    screw.lead_mm = kLead_mm;
    run.screw = screw;
    for (int i = 0; i < 120; ++i) {
        const double from = i % 2 == 0 ? 100.0 : 600.0;
        run.motion.push_back({5.0 * i, 5.0 * (i + 1), from, i % 2 == 0 ? 600.0 : 100.0,
                              (i % 2 == 0 ? 1 : -1) * kSpeed_mm_s * 60});
    }
    return run;
}

double steadyTorque_Nm() {
    const double omega = 2 * M_PI * kSpeed_mm_s / kLead_mm;
    return kCoulomb_Nm + kViscous_Nm_s * omega;
}

}  // namespace

// Signed samples 3.7 s apart straddle most reversals. Squaring a torque
// interpolated from +τ to −τ gives τ²/3 in between; the mean of τ² is τ²
// throughout, since the axis never stops.
TEST(DriveTorque, signedSamplesAcrossReversalsGiveTheMeanOfTheSquare) {
    RunData run = reversingRun();
    run.torque_Nm.name = QStringLiteral("torque_Nm");
    for (double t = 0.3; t < 600; t += 3.7) {
        const bool forward = int(t / 5) % 2 == 0;
        run.torque_Nm.time_s.push_back(t);
        run.torque_Nm.value.push_back(forward ? steadyTorque_Nm() : -steadyTorque_Nm());
    }
    const std::vector<double> mean = meanTorqueSquaredPerStep(run, run.motion, 300, 2.0);
    ASSERT_EQ(mean.size(), 300u);
    const double expected = steadyTorque_Nm() * steadyTorque_Nm();
    for (std::size_t k = 0; k < mean.size(); ++k)
        ASSERT_NEAR(mean[k], expected, 1e-6 * expected) << "step " << k;
}

// Without motion segments there are no speed changes to explain the torque
// by: the squared samples are averaged over each step.
TEST(DriveTorque, withoutMotionTheSquaredSamplesAreAveragedOverEachStep) {
    RunData run = reversingRun();
    const std::vector<MotionSegment> motion = run.motion;
    run.motion.clear();
    run.torque_Nm.name = QStringLiteral("torque_Nm");
    run.torque_Nm.time_s = {0.5, 1.5, 2.5, 4.5, 5.5};
    run.torque_Nm.value = {1, -3, 2, -2, 4};
    const std::vector<double> mean = meanTorqueSquaredPerStep(run, motion, 4, 2.0);
    // Steps [0,2): 1 and 9; [2,4): 4; [4,6): 4 and 16; [6,8): no sample,
    // the last square held.
    EXPECT_DOUBLE_EQ(mean[0], 5);
    EXPECT_DOUBLE_EQ(mean[1], 4);
    EXPECT_DOUBLE_EQ(mean[2], 10);
    EXPECT_DOUBLE_EQ(mean[3], 16);
}
