// The heat a step receives depends on the motion, not on how it is passed:
// the whole run's segments every step, the same with the dwells left out as
// gaps, only the segments that overlap the step, or the run cut once into a
// NutPath (as an identification does for its hundreds of simulations).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "core/physics/NutPath.h"
#include "core/physics/ScrewThermalModel.h"
#include "tests/physics/PhysicsTestSupport.h"

namespace driftlab::physics {
namespace {

enum class Passing { WholeWithDwells, WholeWithGaps, OverlappingWindow, CutOnce };

constexpr double kStep_s = 0.7;       // never aligned with a segment boundary
constexpr std::size_t kSteps = 5143;  // 3600 s: 5142 steps end 0.6 s short

ScrewThermalModel simulate(const std::vector<MotionSegment>& motion, Passing passing,
                           const ScrewThermalParameters& p = {}) {
    ScrewThermalModel model(p, 20);
    StepConditions c;
    c.dt_s = kStep_s;
    c.ambient_begin_C = c.ambient_end_C = 20;
    std::vector<MotionSegment> list = motion;
    if (passing == Passing::WholeWithGaps)
        std::erase_if(list, [](const MotionSegment& s) { return s.isDwell(); });
    const std::span<const MotionSegment> all(list);
    const NutPath path(p, list, kStep_s, kSteps);
    for (std::size_t k = 0; k < kSteps; ++k) {
        const double t0 = model.time_s(), t1 = t0 + c.dt_s;
        if (passing == Passing::CutOnce) {
            c.nut_path = &path;
            c.nut_path_step = k;
        } else if (passing == Passing::OverlappingWindow) {
            auto first = std::find_if(list.begin(), list.end(),
                                      [&](const MotionSegment& s) { return s.end_s > t0; });
            auto last = std::find_if(first, list.end(),
                                     [&](const MotionSegment& s) { return s.start_s >= t1; });
            c.motion = std::span<const MotionSegment>(first, last);
        } else {
            c.motion = all;
        }
        model.step(c);
    }
    return model;
}

// Five 10 min reciprocation blocks, each followed by a 100 s dwell, then 100 s
// at rest past the last segment.
std::vector<MotionSegment> blocksWithDwells() {
    std::vector<MotionSegment> motion;
    double t = 0;
    while (t < 3000 - 1e-9) {
        test::appendReciprocation(motion, 210, 490, 8000, t, 600);
        t += 600;
        test::appendDwell(motion, motion.back().to_mm, t, 100);
        t += 100;
    }
    return motion;
}

TEST(MotionStep, HeatDoesNotDependOnHowTheMotionIsPassed) {
    // The steps reach past every segment.
    ASSERT_LT(blocksWithDwells().back().end_s, kSteps * kStep_s - 50);
    // A speed law and forced convection on top of the defaults: a path cut
    // once stores heat per watt, and the power must still follow the speed.
    ScrewThermalParameters speedLaws;
    speedLaws.nut_heat_exponent = 1.3;
    speedLaws.h1_forced_W_m2K = 0.4;
    speedLaws.forced_exponent = 0.7;
    for (const ScrewThermalParameters& p : {ScrewThermalParameters{}, speedLaws}) {
        const auto motion = blocksWithDwells();
        const ScrewThermalModel reference = simulate(motion, Passing::WholeWithDwells, p);
        ASSERT_GT(reference.energy().nut_J, 1e4);
        for (Passing passing :
             {Passing::WholeWithGaps, Passing::OverlappingWindow, Passing::CutOnce}) {
            const ScrewThermalModel model = simulate(motion, passing, p);
            // The same segments reach the same deposition calls: equal to round-off.
            EXPECT_NEAR(model.energy().nut_J, reference.energy().nut_J,
                        1e-9 * reference.energy().nut_J);
            EXPECT_NEAR(model.energy().bearings_J, reference.energy().bearings_J,
                        1e-9 * reference.energy().bearings_J);
            EXPECT_NEAR(model.energy().convected_J, reference.energy().convected_J,
                        1e-9 * reference.energy().nut_J);
            double worst = 0;
            for (std::size_t i = 0; i < model.temperatures_C().size(); ++i)
                worst = std::max(
                    worst, std::abs(model.temperatures_C()[i] - reference.temperatures_C()[i]));
            EXPECT_LT(worst, 1e-9) << "passing " << static_cast<int>(passing);
        }
    }
}

// A path is used only on the screw, grid, step and motion it was cut for, and
// motion off the screw is refused when it is cut, as a step refuses it.
TEST(MotionStep, PathFitsOnlyWhatItWasCutFor) {
    const auto motion = blocksWithDwells();
    const ScrewThermalParameters p;
    const NutPath path(p, motion, kStep_s, kSteps);
    EXPECT_EQ(path.steps(), kSteps);
    EXPECT_TRUE(path.fits(p, kStep_s, motion.size(), kSteps));
    EXPECT_FALSE(path.fits(p, 2 * kStep_s, motion.size(), kSteps));
    EXPECT_FALSE(path.fits(p, kStep_s, motion.size() - 1, kSteps));
    EXPECT_FALSE(path.fits(p, kStep_s, motion.size(), kSteps + 1));
    for (auto change : {+[](ScrewThermalParameters& q) { q.cells *= 2; },
                        +[](ScrewThermalParameters& q) { q.lead_m *= 2; },
                        +[](ScrewThermalParameters& q) { q.nut_length_m *= 2; },
                        +[](ScrewThermalParameters& q) { q.fixed_end_axis_mm += 1; }}) {
        ScrewThermalParameters other = p;
        change(other);
        EXPECT_FALSE(path.fits(other, kStep_s, motion.size(), kSteps));
    }
    // Heat coefficients are not part of the cut.
    ScrewThermalParameters hotter = p;
    hotter.c_nut_W_per_rad_s *= 3;
    hotter.h_W_m2K *= 2;
    EXPECT_TRUE(path.fits(hotter, kStep_s, motion.size(), kSteps));

    std::vector<MotionSegment> overrun = motion;
    overrun[3].to_mm = p.length_m * 1e3 + 10;
    try {
        NutPath(p, overrun, kStep_s, kSteps);
        ADD_FAILURE() << "motion off the screw was cut";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("outside the screw"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace driftlab::physics
