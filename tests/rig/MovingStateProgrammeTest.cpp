// The moving-state programme: what the axis does and when the interferometer reads.
#include <gtest/gtest.h>

#include "core/rig/MovingStateProgramme.h"

using namespace driftlab;
using namespace driftlab::rig;

namespace {

MovingStateSpec s1Spec() {
    MovingStateSpec spec;
    spec.feed_mm_min = 8000;
    spec.range_mm = {210, 490};
    spec.targets_mm = equallySpacedTargets({0, 700}, 11, 10);
    return spec;
}

}  // namespace

TEST(MovingStateProgramme, targetsAreEquallySpacedInsideTheTravel) {
    const auto targets = equallySpacedTargets({0, 700}, 11, 10);
    ASSERT_EQ(targets.size(), 11u);
    EXPECT_DOUBLE_EQ(targets.front(), 10);
    EXPECT_DOUBLE_EQ(targets.back(), 690);
    EXPECT_DOUBLE_EQ(targets[1] - targets[0], 68);
}

TEST(MovingStateProgramme, motionIsContinuousInTimeAndPlace) {
    const Programme p = buildMovingStateProgramme(s1Spec());
    ASSERT_FALSE(p.motion.empty());
    EXPECT_DOUBLE_EQ(p.motion.front().start_s, 0);
    for (std::size_t i = 1; i < p.motion.size(); ++i) {
        EXPECT_NEAR(p.motion[i].start_s, p.motion[i - 1].end_s, 1e-9) << i;
        EXPECT_DOUBLE_EQ(p.motion[i].from_mm, p.motion[i - 1].to_mm) << i;
        EXPECT_GT(p.motion[i].end_s, p.motion[i].start_s) << i;
    }
    EXPECT_NEAR(p.motion.back().end_s, p.duration_s, 1e-9);
}

TEST(MovingStateProgramme, warmUpReciprocatesOverTheRangeAtTheFeed) {
    const Programme p = buildMovingStateProgramme(s1Spec());
    double reciprocating_s = 0;
    for (const MotionSegment& m : p.motion) {
        if (std::abs(m.feed_mm_min) != 8000) continue;
        EXPECT_TRUE((m.from_mm == 210 && m.to_mm == 490) || (m.from_mm == 490 && m.to_mm == 210));
        EXPECT_NEAR(m.end_s - m.start_s, 280.0 / 8000 * 60, 1e-9);
        EXPECT_EQ(m.feed_mm_min > 0, m.to_mm > m.from_mm);
        EXPECT_LT(m.end_s, 7200 + 1e-6) << "no traversing after the warm-up";
        reciprocating_s += m.end_s - m.start_s;
    }
    // 2 h of warm-up in 10 min blocks, less the interferometer passes between them.
    EXPECT_GT(reciprocating_s, 0.8 * 7200);
    EXPECT_LT(reciprocating_s, 7200);
}

TEST(MovingStateProgramme, everyCycleReadsEachTargetOnceInEachDirection) {
    const MovingStateSpec spec = s1Spec();
    const Programme p = buildMovingStateProgramme(spec);
    std::map<int, std::vector<MeasurementEvent>> cycles;
    for (const MeasurementEvent& e : p.measurements) cycles[e.cycle].push_back(e);
    // Cold pass, ~10 warm-up passes (one per 10 min block), 6 cool-down passes (every 10 min for 1
    // h).
    EXPECT_GE(cycles.size(), 1u + 10u + 6u);
    EXPECT_LE(cycles.size(), 1u + 12u + 6u);
    EXPECT_LT(cycles.at(0).back().time_s, 200) << "cycle 0 is the cold reference at the start";
    for (const auto& [cycle, events] : cycles) {
        ASSERT_EQ(events.size(), 22u) << cycle;
        for (std::size_t i = 0; i < 11; ++i) {
            EXPECT_EQ(events[i].direction, Direction::Positive);
            EXPECT_DOUBLE_EQ(events[i].target_mm, spec.targets_mm[i]);
            EXPECT_EQ(events[21 - i].direction, Direction::Negative);
            EXPECT_DOUBLE_EQ(events[21 - i].target_mm, spec.targets_mm[i]);
        }
    }
    // The nut stands at the target while it is read.
    for (const MeasurementEvent& e : p.measurements) {
        const AxisState s = axisStateAt(p.motion, e.time_s);
        EXPECT_DOUBLE_EQ(s.position_mm, e.target_mm);
        EXPECT_EQ(s.feed_mm_min, 0);
    }
    EXPECT_NEAR(p.duration_s, 7200 + 3600, 300);
}

TEST(MovingStateProgramme, axisStateInterpolatesAlongASegment) {
    const std::vector<MotionSegment> motion{{0, 10, 0, 100, 600}, {10, 20, 100, 100, 0}};
    EXPECT_DOUBLE_EQ(axisStateAt(motion, 2.5).position_mm, 25);
    EXPECT_DOUBLE_EQ(axisStateAt(motion, 2.5).feed_mm_min, 600);
    EXPECT_DOUBLE_EQ(axisStateAt(motion, 15).position_mm, 100);
    EXPECT_DOUBLE_EQ(axisStateAt(motion, 15).feed_mm_min, 0);
    EXPECT_DOUBLE_EQ(axisStateAt(motion, 99).position_mm, 100);
}

TEST(MovingStateProgramme, aSpecThatCannotRunIsRefused) {
    MovingStateSpec spec = s1Spec();
    spec.feed_mm_min = 0;
    EXPECT_THROW(buildMovingStateProgramme(spec), std::invalid_argument);
    spec = s1Spec();
    spec.range_mm = {300, 300};
    EXPECT_THROW(buildMovingStateProgramme(spec), std::invalid_argument);
    spec = s1Spec();
    spec.targets_mm.clear();
    EXPECT_THROW(buildMovingStateProgramme(spec), std::invalid_argument);
    spec = s1Spec();
    spec.warmup_s = -1;
    EXPECT_THROW(buildMovingStateProgramme(spec), std::invalid_argument);
}
