// Parameters and step conditions that cannot be simulated are rejected with
// std::invalid_argument naming what is wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/physics/ScrewThermalModel.h"

namespace driftlab::physics {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void expectRejected(const std::function<void()>& action, const std::string& fragment) {
    try {
        action();
        ADD_FAILURE() << "accepted; expected a rejection mentioning \"" << fragment << '"';
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos)
            << "message: " << error.what() << "; expected to mention \"" << fragment << '"';
    }
}

void expectParameterRejected(const std::function<void(ScrewThermalParameters&)>& change,
                             const std::string& fragment) {
    ScrewThermalParameters p;
    change(p);
    expectRejected([&] { ScrewThermalModel model(p, 20); }, fragment);
}

TEST(Validation, RejectsParametersThatCannotBeSimulated) {
    expectParameterRejected([](auto& p) { p.diameter_m = 0; }, "diameter_m");
    expectParameterRejected([](auto& p) { p.diameter_m = -0.04; }, "diameter_m");
    expectParameterRejected([](auto& p) { p.length_m = -1; }, "length_m");
    expectParameterRejected([](auto& p) { p.nut_length_m = 0; }, "nut_length_m");
    expectParameterRejected([](auto& p) { p.lead_m = kNaN; }, "lead_m");
    expectParameterRejected([](auto& p) { p.conductivity_W_mK = 0; }, "conductivity_W_mK");
    expectParameterRejected([](auto& p) { p.density_kg_m3 = -7850; }, "density_kg_m3");
    expectParameterRejected([](auto& p) { p.h_W_m2K = -1; }, "h_W_m2K");
    expectParameterRejected([](auto& p) { p.c_nut_W_per_rad_s = -0.1; }, "c_nut_W_per_rad_s");
    expectParameterRejected([](auto& p) { p.cells = 2; }, "cells");
    expectParameterRejected([](auto& p) { p.cells = 0; }, "cells");
    expectParameterRejected([](auto& p) { p.theta = 0.4; }, "theta");
    expectParameterRejected([](auto& p) { p.theta = 1.01; }, "theta");
    expectParameterRejected([](auto& p) { p.theta = kNaN; }, "theta");
    expectRejected([] { ScrewThermalModel model(ScrewThermalParameters{}, kNaN); },
                   "initial temperature");
    // The limits themselves are accepted.
    ScrewThermalParameters p;
    p.cells = 3;
    p.theta = 0.5;
    EXPECT_NO_THROW(ScrewThermalModel(p, 20));
}

TEST(Validation, RejectsStepsThatCannotBeTaken) {
    ScrewThermalModel model(ScrewThermalParameters{}, 20);
    auto stepWith = [&](auto change) {
        return [&model, change] {
            StepConditions c;
            change(c);
            model.step(c);
        };
    };
    expectRejected(stepWith([](StepConditions& c) { c.dt_s = 0; }), "time step");
    expectRejected(stepWith([](StepConditions& c) { c.dt_s = -1; }), "time step");
    expectRejected(stepWith([](StepConditions& c) { c.dt_s = kNaN; }), "time step");
    expectRejected(stepWith([](StepConditions& c) { c.dt_s = 1.0 / 0.0; }), "time step");
    expectRejected(stepWith([](StepConditions& c) { c.ambient_begin_C = kNaN; }), "ambient");
    expectRejected(stepWith([](StepConditions& c) { c.ambient_end_C = kNaN; }), "ambient");
    EXPECT_EQ(model.time_s(), 0);  // nothing was stepped
}

// Default screw: fixed end at axis −40 mm, free end at 860 mm.
TEST(Validation, RejectsMotionThatLeavesTheScrew) {
    for (MotionSegment bad :
         {MotionSegment{0, 1, 800, 900, 6000}, MotionSegment{0, 1, -100, 100, 12000}}) {
        ScrewThermalModel model(ScrewThermalParameters{}, 20);
        const std::vector<MotionSegment> motion{bad};
        StepConditions c;
        c.motion = motion;
        expectRejected([&] { model.step(c); }, "outside the screw");
    }
}

// A step refused for its motion must not leave heat behind: a caller that
// catches the error and goes on must see exactly the accepted steps.
TEST(Validation, RejectedStepLeavesTheModelUnchanged) {
    ScrewThermalParameters p;
    ScrewThermalModel model(p, 20);
    // In range for the first half second, then beyond the free end (860 mm).
    const std::vector<MotionSegment> bad{{0, 0.5, 400, 500, 12000}, {0.5, 1, 500, 900, 48000}};
    StepConditions c;
    c.motion = bad;
    expectRejected([&] { model.step(c); }, "outside the screw");
    EXPECT_EQ(model.time_s(), 0);
    EXPECT_EQ(model.energy().heatIn_J(), 0);

    c.motion = {};
    model.step(c);
    double warmest = 0;
    for (double T : model.temperatures_C()) warmest = std::max(warmest, T - 20);
    // Round-off of one solve at a uniform 20 °C is ~1e-15 K; the leaked heat
    // of the refused half second would have warmed the screw by 0.04 K.
    EXPECT_NEAR(warmest, 0, 1e-12);
    EXPECT_EQ(model.energy().heatIn_J(), 0);
}

}  // namespace
}  // namespace driftlab::physics
