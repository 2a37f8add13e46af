// The motor heat's input, the mean of τ² over each step of the screw
// simulation, from a drive's torque log and the axis motion.
#include <gtest/gtest.h>

#include <cmath>

#include "core/models/DriveTorque.h"

using namespace driftlab;
using namespace driftlab::models;

namespace {

constexpr double kLead_mm = 10, kCoulomb_Nm = 0.8, kViscous_Nm_s = 0.002, kInertia_kgm2 = 0.004;

Screw screw() {
    Screw s;
    s.length_mm = 800;
    s.diameter_mm = 32;
    s.lead_mm = kLead_mm;
    return s;
}

double omegaOf(double v_mm_s) {
    return 2 * M_PI * v_mm_s / kLead_mm;
}

/// Strokes of 300 mm at 100 and 50 mm/s in turn between dwells of 3 s, each
/// start and stop
/// a 0.2 s ramp written as ten 0.02 s segments (as a controller's position
/// trace reads), for 600 s.
struct DriveRun {
    RunData run;
    std::vector<double> acceleration_mm_s2;  ///< per segment
};

DriveRun strokes() {
    DriveRun d;
    d.run.run_id = QStringLiteral("R1");
    d.run.screw = screw();
    const double ramp_s = 0.2, slice_s = 0.02;
    double t = 0, x = 100, direction = 1, v = 100;
    auto add = [&](double duration, double speed, double accel) {
        const double to = x + direction * speed * duration;
        d.run.motion.push_back({t, t + duration, x, to, direction * speed * 60});
        d.acceleration_mm_s2.push_back(direction * accel);
        t += duration;
        x = to;
    };
    while (t < 600) {
        const double a = v / ramp_s;
        add(3, 0, 0);
        for (int i = 0; i < 10; ++i) add(slice_s, a * (i + 0.5) * slice_s, a);
        add((300 - v * ramp_s) / v, v, 0);
        for (int i = 9; i >= 0; --i) add(slice_s, a * (i + 0.5) * slice_s, -a);
        direction = -direction;
        v = v == 100 ? 50 : 100;
    }
    return d;
}

/// τ = F_c·sgn ω + b·ω + J·α at time t.
double torqueAt(const DriveRun& d, double t) {
    for (std::size_t s = 0; s < d.run.motion.size(); ++s) {
        const MotionSegment& m = d.run.motion[s];
        if (t < m.start_s || t >= m.end_s) continue;
        const double v = (m.to_mm - m.from_mm) / (m.end_s - m.start_s);
        if (v == 0) return 0;
        return std::copysign(kCoulomb_Nm, v) + kViscous_Nm_s * omegaOf(v) +
               kInertia_kgm2 * omegaOf(d.acceleration_mm_s2[s]);
    }
    return 0;
}

}  // namespace

// Instantaneous samples 0.37 s apart land in a ramp one time in twenty;
// identified over the whole run, the drive gives the mean of τ² over every
// minute within 10 %, where the squared samples' own means miss by far more.
TEST(DriveTorque, anInstantaneousLogIsExplainedByTheMotion) {
    DriveRun d = strokes();
    d.run.torque_Nm.name = QStringLiteral("torque_Nm");
    for (double t = 0.11; t < 600; t += 0.37) {
        d.run.torque_Nm.time_s.push_back(t);
        d.run.torque_Nm.value.push_back(torqueAt(d, t));
    }
    const auto drive = identifyDriveTorque(std::span(&d.run, 1));
    ASSERT_TRUE(drive);
    EXPECT_NEAR(drive->coulomb_Nm, kCoulomb_Nm, 0.01 * kCoulomb_Nm);
    EXPECT_NEAR(drive->viscous_Nm_per_rad_s, kViscous_Nm_s, 0.01 * kViscous_Nm_s);
    // About 80 samples land in a ramp, half of them braking: J² is known to
    // some 25 % by chance alone.
    EXPECT_NEAR(drive->inertia_squared_kg2m4, kInertia_kgm2 * kInertia_kgm2,
                0.4 * kInertia_kgm2 * kInertia_kgm2);

    const std::vector<double> sampled = meanTorqueSquaredPerStep(d.run, d.run.motion, 300, 2.0);
    d.run.drive_torque = drive;
    const std::vector<double> modelled = meanTorqueSquaredPerStep(d.run, d.run.motion, 300, 2.0);
    double worstModelled = 0, worstSampled = 0;
    for (int minute = 0; minute < 10; ++minute) {
        double truth = 0, fromModel = 0, fromSamples = 0;
        for (int i = 0; i < 60000; ++i)
            truth += std::pow(torqueAt(d, minute * 60 + (i + 0.5) * 1e-3), 2);
        truth /= 60000;
        for (int k = 30 * minute; k < 30 * (minute + 1); ++k)
            fromModel += modelled[std::size_t(k)] / 30, fromSamples += sampled[std::size_t(k)] / 30;
        worstModelled = std::max(worstModelled, std::abs(fromModel / truth - 1));
        worstSampled = std::max(worstSampled, std::abs(fromSamples / truth - 1));
    }
    // Mean τ² per minute, worst relative error of each.
    EXPECT_LT(worstModelled, 0.10);
    EXPECT_GT(worstSampled, 2 * worstModelled)
        << "drive model " << worstModelled << ", squared samples " << worstSampled;
}

// A log that never goes negative is an RMS over the interval (a drive's I²t
// channel): it is not explained again, its squares are averaged per step.
TEST(DriveTorque, anRmsLogIsAveragedOverEachStep) {
    DriveRun d = strokes();
    d.run.torque_Nm.name = QStringLiteral("torque_Nm");
    d.run.torque_Nm.time_s = {0.5, 1.5, 2.5, 4.5, 5.5};
    d.run.torque_Nm.value = {1, 3, 2, 2, 4};
    EXPECT_FALSE(identifyDriveTorque(std::span(&d.run, 1)));
    const std::vector<double> mean = meanTorqueSquaredPerStep(d.run, d.run.motion, 4, 2.0);
    // Steps [0,2): 1 and 9; [2,4): 4; [4,6): 4 and 16; [6,8): no sample,
    // the last square held.
    EXPECT_DOUBLE_EQ(mean[0], 5);
    EXPECT_DOUBLE_EQ(mean[1], 4);
    EXPECT_DOUBLE_EQ(mean[2], 10);
    EXPECT_DOUBLE_EQ(mean[3], 16);
}
