// The heat a step receives depends on the motion, not on how it is passed:
// the whole run's segments every step, the same with the dwells left out as
// gaps, or only the segments that overlap the step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>

#include "core/physics/ScrewThermalModel.h"
#include "tests/physics/PhysicsTestSupport.h"

namespace driftlab::physics {
namespace {

enum class Passing { WholeWithDwells, WholeWithGaps, OverlappingWindow };

ScrewThermalModel simulate(const std::vector<MotionSegment>& motion, Passing passing) {
    ScrewThermalParameters p;
    ScrewThermalModel model(p, 20);
    StepConditions c;
    c.dt_s = 0.7;  // never aligned with a segment boundary
    c.ambient_begin_C = c.ambient_end_C = 20;
    std::vector<MotionSegment> list = motion;
    if (passing == Passing::WholeWithGaps)
        std::erase_if(list, [](const MotionSegment& s) { return s.isDwell(); });
    const std::span<const MotionSegment> all(list);
    while (model.time_s() < 3600 - 1e-9) {
        const double t0 = model.time_s(), t1 = t0 + c.dt_s;
        if (passing == Passing::OverlappingWindow) {
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

// 50 min of 10 min reciprocation blocks with 100 s dwells, then 10 min at
// rest past the last segment.
TEST(MotionStep, HeatDoesNotDependOnHowTheMotionIsPassed) {
    std::vector<MotionSegment> motion;
    double t = 0;
    while (t < 3000 - 1e-9) {
        test::appendReciprocation(motion, 210, 490, 8000, t, 600);
        t += 600;
        test::appendDwell(motion, motion.back().to_mm, t, 100);
        t += 100;
    }
    const ScrewThermalModel reference = simulate(motion, Passing::WholeWithDwells);
    ASSERT_GT(reference.energy().nut_J, 1e4);
    for (Passing passing : {Passing::WholeWithGaps, Passing::OverlappingWindow}) {
        const ScrewThermalModel model = simulate(motion, passing);
        // The same segments reach the same deposition calls: equal to round-off.
        EXPECT_NEAR(model.energy().nut_J, reference.energy().nut_J,
                    1e-9 * reference.energy().nut_J);
        EXPECT_NEAR(model.energy().bearings_J, reference.energy().bearings_J,
                    1e-9 * reference.energy().bearings_J);
        double worst = 0;
        for (std::size_t i = 0; i < model.temperatures_C().size(); ++i)
            worst = std::max(worst,
                             std::abs(model.temperatures_C()[i] - reference.temperatures_C()[i]));
        EXPECT_LT(worst, 1e-9) << "passing " << static_cast<int>(passing);
    }
}

}  // namespace
}  // namespace driftlab::physics
