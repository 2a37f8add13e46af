// ISO 230-2 targets and the positioning programme: what the axis does and
// when the interferometer reads, checked against the standard's rules.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "core/iso/Iso230_2.h"
#include "core/procedures/ProcedurePlan.h"

using namespace driftlab;
using namespace driftlab::procedures;

namespace {

PositioningSpec spanSpec(RangeMm span_mm, double perMetre, unsigned seed = 1) {
    PositioningSpec s;
    s.span_mm = span_mm;
    s.targets_per_metre = perMetre;
    s.seed = seed;
    return s;
}

/// The last moving segment that ended at or before `time_s`.
const MotionSegment* lastMoveBefore(const rig::Programme& p, double time_s) {
    const MotionSegment* last = nullptr;
    for (const MotionSegment& m : p.motion)
        if (!m.isDwell() && m.end_s <= time_s + 1e-9) last = &m;
    return last;
}

/// The standstill the reading at `time_s` and `x_mm` is taken in.
const MotionSegment* dwellAt(const rig::Programme& p, double time_s, double x_mm) {
    for (const MotionSegment& m : p.motion)
        if (m.isDwell() && m.from_mm == x_mm && m.start_s <= time_s + 1e-9 &&
            time_s <= m.end_s + 1e-9)
            return &m;
    return nullptr;
}

}  // namespace

TEST(PositioningTargets, atLeastFivePerMetreAndFiveInAllOverTheSpan) {
    for (RangeMm span : {RangeMm{5, 695}, RangeMm{0, 300}, RangeMm{0, 2000}, RangeMm{100, 110}})
        for (double perMetre : {5.0, 10.0, 12.5}) {
            const auto spec = spanSpec(span, perMetre);
            const std::vector<double> t = positioningTargets(spec);
            const double length_m = (span.to_mm - span.from_mm) / 1000;
            SCOPED_TRACE(testing::Message() << span.from_mm << ".." << span.to_mm << " at "
                                            << perMetre << "/m: " << t.size() << " targets");
            EXPECT_GE(t.size(), 5u);
            EXPECT_GE(double(t.size()), perMetre * length_m - 1e-9);
            EXPECT_LE(double(t.size()), std::max(5.0, perMetre * length_m + 1));  // no more
            EXPECT_EQ(t.front(), span.from_mm);
            EXPECT_EQ(t.back(), span.to_mm);
            for (std::size_t i = 1; i < t.size(); ++i) EXPECT_GT(t[i], t[i - 1]);
            for (double x : t) EXPECT_NEAR(x * 1000, std::round(x * 1000), 1e-6) << "0.001 mm";
        }
}

TEST(PositioningTargets, innerTargetsAreShiftedByLessThanTenPercentAndNotAllAlike) {
    for (double irregularity : {0.0, 0.05, 0.099}) {
        auto spec = spanSpec({0, 1000}, 10);
        spec.irregularity = irregularity;
        const std::vector<double> t = positioningTargets(spec);
        const double interval = 1000.0 / double(t.size() - 1);
        std::set<double> shifts;
        for (std::size_t i = 1; i + 1 < t.size(); ++i) {
            const double shift = t[i] - interval * double(i);
            EXPECT_LT(std::abs(shift), 0.1 * interval) << i;
            EXPECT_LE(std::abs(shift), irregularity * interval + 0.0005) << i;
            shifts.insert(std::round(shift * 1000));
        }
        if (irregularity > 0)
            EXPECT_GT(shifts.size(), t.size() / 2)
                << "the shifts must differ from target to target";
        else
            EXPECT_EQ(shifts.size(), 1u);
    }
}

TEST(PositioningTargets, theSameSeedGivesTheSameTargetsAnotherSeedOthers) {
    const auto a = positioningTargets(spanSpec({5, 695}, 10, 7));
    EXPECT_EQ(a, positioningTargets(spanSpec({5, 695}, 10, 7)));
    const auto b = positioningTargets(spanSpec({5, 695}, 10, 8));
    ASSERT_EQ(a.size(), b.size());
    EXPECT_NE(a, b);
    EXPECT_EQ(a.front(), b.front());
    EXPECT_EQ(a.back(), b.back());
}

class PositioningProgramme : public testing::TestWithParam<ApproachOrder> {
protected:
    PositioningSpec spec() const {
        PositioningSpec s;  // 5 … 695 mm in a 0 … 700 mm travel, 5 cycles
        s.order = GetParam();
        return s;
    }
};

TEST_P(PositioningProgramme, readsEveryTargetOncePerCycleInEachDirection) {
    const PositioningSpec s = spec();
    const rig::Programme p = buildPositioningProgramme(s);
    const std::vector<double> targets = positioningTargets(s);
    std::map<std::tuple<int, double, Direction>, int> seen;
    for (const rig::MeasurementEvent& m : p.measurements) {
        EXPECT_GE(m.cycle, 1);
        EXPECT_LE(m.cycle, s.cycles);
        ++seen[{m.cycle, m.target_mm, m.direction}];
    }
    EXPECT_EQ(p.measurements.size(), targets.size() * 2 * std::size_t(s.cycles));
    for (int c = 1; c <= s.cycles; ++c)
        for (double x : targets)
            for (Direction d : {Direction::Positive, Direction::Negative})
                EXPECT_EQ((seen[{c, x, d}]), 1) << "cycle " << c << " target " << x;
}

TEST_P(PositioningProgramme, positiveReadingsAreApproachedFromBelowNegativeFromAbove) {
    const rig::Programme p = buildPositioningProgramme(spec());
    for (const rig::MeasurementEvent& m : p.measurements) {
        const MotionSegment* move = lastMoveBefore(p, m.time_s);
        ASSERT_TRUE(move) << m.time_s;
        EXPECT_EQ(move->to_mm, m.target_mm);
        if (m.direction == Direction::Positive)
            EXPECT_LT(move->from_mm, m.target_mm) << "at " << m.time_s;
        else
            EXPECT_GT(move->from_mm, m.target_mm) << "at " << m.time_s;
    }
}

TEST_P(PositioningProgramme, overrunsTheEndTargetsAndStaysInTheTravel) {
    const PositioningSpec s = spec();
    const rig::Programme p = buildPositioningProgramme(s);
    const std::vector<double> targets = positioningTargets(s);
    double low = 1e9, high = -1e9;
    for (const MotionSegment& m : p.motion) {
        low = std::min({low, m.from_mm, m.to_mm});
        high = std::max({high, m.from_mm, m.to_mm});
    }
    EXPECT_EQ(low, targets.front() - s.overrun_mm);
    EXPECT_EQ(high, targets.back() + s.overrun_mm);
    EXPECT_GE(low, 0);
    EXPECT_LE(high, 700);
}

TEST_P(PositioningProgramme, eachReadingEndsADwellAtStandstill) {
    const PositioningSpec s = spec();
    const rig::Programme p = buildPositioningProgramme(s);
    for (const rig::MeasurementEvent& m : p.measurements) {
        const MotionSegment* dwell = dwellAt(p, m.time_s, m.target_mm);
        ASSERT_TRUE(dwell) << "no standstill at the reading at " << m.time_s;
        EXPECT_GE(m.time_s - dwell->start_s, s.dwell_s - 1e-6);
    }
}

TEST_P(PositioningProgramme, motionIsContinuousInTimeAndPlace) {
    const rig::Programme p = buildPositioningProgramme(spec());
    ASSERT_FALSE(p.motion.empty());
    EXPECT_EQ(p.motion.front().start_s, 0);
    for (std::size_t i = 1; i < p.motion.size(); ++i) {
        EXPECT_EQ(p.motion[i].start_s, p.motion[i - 1].end_s) << i;
        EXPECT_EQ(p.motion[i].from_mm, p.motion[i - 1].to_mm) << i;
        EXPECT_GT(p.motion[i].end_s, p.motion[i].start_s) << i;
        if (!p.motion[i].isDwell()) {
            EXPECT_EQ(std::abs(p.motion[i].feed_mm_min), 3000);
        }
    }
    EXPECT_EQ(p.motion.back().end_s, p.duration_s);
    EXPECT_EQ(p.motion.back().to_mm, p.motion.front().from_mm) << "ends where it started";
}

TEST_P(PositioningProgramme, isEvaluatedByIso230_2) {
    const PositioningSpec s = spec();
    const rig::Programme p = buildPositioningProgramme(s);
    // Synthetic axis: a periodic pitch error, 2.5 µm of backlash, 0.3 µm of noise.
    std::mt19937_64 rng(3);
    std::normal_distribution<double> noise(0, 0.3);
    std::vector<iso::Reading> readings;
    for (const rig::MeasurementEvent& m : p.measurements) {
        const double half = m.direction == Direction::Positive ? 1.25 : -1.25;
        readings.push_back({m.target_mm, m.direction, m.cycle,
                            4 * std::sin(m.target_mm / 70) + half + noise(rng)});
    }
    const iso::Evaluation e = iso::evaluate(readings);
    ASSERT_TRUE(e.ok()) << e.error.toStdString();
    EXPECT_EQ(e.cycles, s.cycles);
    EXPECT_EQ(e.targets.size(), positioningTargets(s).size());
    EXPECT_TRUE(e.skipped.isEmpty()) << e.skipped.join("; ").toStdString();
    EXPECT_TRUE(e.warnings.isEmpty()) << e.warnings.join("; ").toStdString();
    for (const iso::TargetResult& t : e.targets) {
        EXPECT_EQ(t.n_up, s.cycles);
        EXPECT_EQ(t.n_down, s.cycles);
        EXPECT_NEAR(t.reversal_um, 2.5, 1.0);
    }
    EXPECT_GT(e.axis.e_um, 6);  // the pitch error spans most of ±4 µm
}

INSTANTIATE_TEST_SUITE_P(Orders, PositioningProgramme,
                         testing::Values(ApproachOrder::Linear, ApproachOrder::Pilgrim),
                         [](const auto& info) {
                             return info.param == ApproachOrder::Linear ? "linear" : "pilgrim";
                         });

TEST(PositioningProgrammeOrder, pilgrimReversesAtEveryTargetLinearOnlyAtTheEnds) {
    auto reversals = [](ApproachOrder order) {
        PositioningSpec s;
        s.order = order;
        s.cycles = 1;
        const rig::Programme p = buildPositioningProgramme(s);
        int count = 0;
        double lastFeed = 0;
        for (const MotionSegment& m : p.motion) {
            if (m.isDwell()) continue;
            if (lastFeed != 0 && (m.feed_mm_min > 0) != (lastFeed > 0)) ++count;
            lastFeed = m.feed_mm_min;
        }
        return count;
    };
    const int targets = int(positioningTargets(PositioningSpec{}).size());
    EXPECT_EQ(reversals(ApproachOrder::Linear), 1);  // up, then down to the park
    EXPECT_EQ(reversals(ApproachOrder::Pilgrim), 2 * targets - 1);
}
