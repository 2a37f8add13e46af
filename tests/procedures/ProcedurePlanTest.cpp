// Planning a procedure into runs; the ISO 230-3 warm-up ended early; the
// change between two passes the stabilisation criterion looks at.
#include <gtest/gtest.h>

#include <stdexcept>

#include "core/procedures/ProcedurePlan.h"
#include "tests/procedures/ProcedureTestSupport.h"

using namespace driftlab;
using namespace driftlab::procedures;
using driftlab::procedures::test::shipped;

TEST(PlanRuns, eachKindBecomesItsRuns) {
    const auto positioning = planRuns(shipped("iso230-2-x-axis.json"));
    ASSERT_EQ(positioning.size(), 1u);
    EXPECT_EQ(positioning[0].kind, RunKind::Positioning);
    EXPECT_EQ(positioning[0].id, QStringLiteral("P1"));
    EXPECT_FALSE(positioning[0].programme.measurements.empty());
    EXPECT_EQ(positioning[0].duration_s, positioning[0].programme.duration_s);
    EXPECT_TRUE(positioning[0].description.startsWith(QStringLiteral("ISO 230-2 positioning")));

    const auto axis = planRuns(shipped("iso230-3-x-axis.json"));
    ASSERT_EQ(axis.size(), 1u);
    EXPECT_EQ(axis[0].kind, RunKind::Moving);
    ASSERT_TRUE(axis[0].warmup);
    EXPECT_EQ(axis[0].warmup->warmup_s, 14400);
    EXPECT_EQ(axis[0].warmup->block_s, 600);
    EXPECT_EQ(axis[0].warmup->targets_mm, rig::equallySpacedTargets({0, 700}, 11, 5));
    EXPECT_EQ(axis[0].stabilisation_um, 1.0);
    EXPECT_EQ(axis[0].feed_mm_min, 8000);
    EXPECT_EQ(axis[0].range_mm, (RangeMm{210, 490}));

    const auto etve = planRuns(shipped("etve-8h.json"));
    ASSERT_EQ(etve.size(), 1u);
    EXPECT_EQ(etve[0].kind, RunKind::Etve);
    ASSERT_TRUE(etve[0].spindle);
    EXPECT_EQ(etve[0].spindle->kind, RunKind::Etve);
    ASSERT_EQ(etve[0].spindle->blocks.size(), 1u);
    EXPECT_EQ(etve[0].spindle->blocks[0].speed_rpm, 0);
    EXPECT_EQ(etve[0].spindle->sample_interval_s, 60);
    EXPECT_EQ(etve[0].duration_s, 28800);
    EXPECT_TRUE(etve[0].programme.motion.empty());

    const auto spindle = planRuns(shipped("spindle-iso230-3.json"));
    ASSERT_EQ(spindle.size(), 1u);
    EXPECT_EQ(spindle[0].kind, RunKind::Spindle);
    ASSERT_TRUE(spindle[0].spindle);
    EXPECT_EQ(spindle[0].spindle->blocks.size(), 5u);
    EXPECT_EQ(spindle[0].duration_s, 9900);

    const auto states = planRuns(shipped("moving-states-s1-s5.json"));
    ASSERT_EQ(states.size(), 5u);
    const double feeds[] = {8000, 6500, 15000, 8000, 8000};
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_EQ(states[i].id, QStringLiteral("S%1").arg(i + 1));
        EXPECT_EQ(states[i].kind, RunKind::Moving);
        EXPECT_EQ(states[i].feed_mm_min, feeds[i]);
        EXPECT_FALSE(states[i].warmup) << "only the ISO 230-3 run stops on stabilisation";
        EXPECT_GT(states[i].duration_s, 7200 + 3600);
    }
    EXPECT_EQ(states[3].range_mm, (RangeMm{0, 210}));
}

TEST(PlanRuns, aRangeOutsideTheTravelCannotBePlanned) {
    Procedure p = shipped("moving-states-s1-s5.json");
    p.travel_mm = {0, 400};  // as a procedure built in code, not parsed, could be
    EXPECT_THROW(planRuns(p), std::invalid_argument);
    p.moving_states.reset();
    EXPECT_THROW(planRuns(p), std::invalid_argument);
}

namespace {

/// The ISO 230-3 run, shortened: at most 1 h of warm-up in 10 min blocks.
PlannedRun shortAxisRun() {
    Procedure p = shipped("iso230-3-x-axis.json");
    p.thermal_distortion->max_warmup_s = 3600;
    p.thermal_distortion->cooldown_s = 1200;
    return planRuns(p).front();
}

/// The end of the warm-up pass of `cycle`: back at the park after its last reading.
double passEnd(const PlannedRun& run, int cycle) {
    double lastReading = 0;
    for (const rig::MeasurementEvent& m : run.programme.measurements)
        if (m.cycle == cycle) lastReading = m.time_s;
    for (const MotionSegment& m : run.programme.motion)
        if (m.start_s >= lastReading && !m.isDwell() && m.to_mm == run.range_mm->from_mm)
            return m.end_s;
    return -1;
}

}  // namespace

TEST(ReplanWarmupEnd, keepsEverythingBeforeTheEndAndCoolsDownAfter) {
    const PlannedRun full = shortAxisRun();
    const double end_s = passEnd(full, 3);
    ASSERT_GT(end_s, 1800);
    ASSERT_LT(end_s, 2400);
    const PlannedRun cut = replanWarmupEnd(full, end_s);
    EXPECT_EQ(cut.warmup->warmup_s, end_s);
    EXPECT_LT(cut.duration_s, full.duration_s);
    EXPECT_EQ(cut.duration_s, cut.programme.duration_s);

    // The prefix: motion and readings up to the end are the original plan's.
    std::size_t motionBefore = 0, readingsBefore = 0;
    while (full.programme.motion[motionBefore].end_s <= end_s) ++motionBefore;
    while (full.programme.measurements[readingsBefore].time_s <= end_s) ++readingsBefore;
    ASSERT_GE(cut.programme.motion.size(), motionBefore);
    ASSERT_GE(cut.programme.measurements.size(), readingsBefore);
    for (std::size_t i = 0; i < motionBefore; ++i)
        EXPECT_EQ(cut.programme.motion[i], full.programme.motion[i]) << i;
    for (std::size_t i = 0; i < readingsBefore; ++i) {
        EXPECT_EQ(cut.programme.measurements[i].time_s, full.programme.measurements[i].time_s);
        EXPECT_EQ(cut.programme.measurements[i].cycle, full.programme.measurements[i].cycle);
        EXPECT_EQ(cut.programme.measurements[i].target_mm,
                  full.programme.measurements[i].target_mm);
    }
    // Then the cool-down: no more reciprocating, a pass every 600 s for 1200 s.
    std::set<int> coolingCycles;
    for (std::size_t i = motionBefore; i < cut.programme.motion.size(); ++i)
        EXPECT_NE(std::abs(cut.programme.motion[i].feed_mm_min), 8000) << i;
    for (std::size_t i = readingsBefore; i < cut.programme.measurements.size(); ++i) {
        EXPECT_GE(cut.programme.measurements[i].time_s, end_s + 600);
        coolingCycles.insert(cut.programme.measurements[i].cycle);
    }
    EXPECT_EQ(coolingCycles, (std::set<int>{4, 5}));
    EXPECT_THROW(replanWarmupEnd(full, 3600 + 1), std::invalid_argument);
    EXPECT_THROW(replanWarmupEnd(planRuns(shipped("moving-states-s1-s5.json")).front(), 600),
                 std::invalid_argument);
}

namespace {

std::vector<PositioningMeasurement> pass(int cycle, double up_um, double down_um) {
    return {{0, cycle, 10, Direction::Positive, up_um},
            {0, cycle, 350, Direction::Positive, up_um * 2},
            {0, cycle, 350, Direction::Negative, down_um * 2},
            {0, cycle, 10, Direction::Negative, down_um}};
}

void append(std::vector<PositioningMeasurement>& to, std::vector<PositioningMeasurement> from) {
    to.insert(to.end(), from.begin(), from.end());
}

}  // namespace

TEST(PassChange, isTheLargestChangeBetweenTheLastTwoCompletePasses) {
    std::vector<PositioningMeasurement> r = pass(0, 100, 100);  // cold reference: ignored
    EXPECT_FALSE(passChange_um(r));
    append(r, pass(1, 5, 4));
    EXPECT_FALSE(passChange_um(r)) << "one warm-up pass is not a change";
    append(r, pass(2, 6, 3.5));
    ASSERT_TRUE(passChange_um(r));
    EXPECT_DOUBLE_EQ(*passChange_um(r), 2.0);  // at 350 mm going up: 12 − 10
    // A pass still being read does not count yet.
    r.push_back({0, 3, 10, Direction::Positive, 50});
    EXPECT_DOUBLE_EQ(*passChange_um(r), 2.0);
    append(r, {{0, 3, 350, Direction::Positive, 12.25},
               {0, 3, 350, Direction::Negative, 7},
               {0, 3, 10.0000000001, Direction::Negative, 3.5}});
    EXPECT_DOUBLE_EQ(*passChange_um(r), 44.0);  // at 10 mm going up: 50 − 6
}
