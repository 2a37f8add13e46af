// The exact nut deposition against energy conservation, a closed-form loss at
// the screw end and brute-force time integration of the nut–cell overlap.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "core/physics/NutHeatDeposition.h"

namespace driftlab::physics {
namespace {

constexpr double kCell = 0.0045;  // 200 cells on 0.9 m
constexpr double kNut = 0.08;
constexpr int kCells = 200;

double sum(const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0);
}

/// Independent reference: the nut centre sampled at the midpoints of `n`
/// sub-intervals, each sub-interval adding P·δt·|nut ∩ cell| / w to the cell.
std::vector<double> bruteForce(double from, double to, double duration, double power, int n) {
    std::vector<double> e(kCells, 0.0);
    const double dt = duration / n;
    for (int j = 0; j < n; ++j) {
        const double c = from + (to - from) * (j + 0.5) / n;
        for (int i = 0; i < kCells; ++i) {
            const double overlap =
                std::min((i + 1) * kCell, c + kNut / 2) - std::max(i * kCell, c - kNut / 2);
            if (overlap > 0) e[static_cast<std::size_t>(i)] += power * dt * overlap / kNut;
        }
    }
    return e;
}

TEST(NutHeatDeposition, StrokeInsideTheScrewDepositsPowerTimesDuration) {
    for (auto [from, to] : {std::pair{0.2, 0.5}, std::pair{0.5, 0.2}, std::pair{0.3001, 0.3013}}) {
        std::vector<double> e(kCells, 0.0);
        const double added = depositNutHeat(e, kCell, kNut, from, to, 2.5, 9.2);
        // Energy is conserved to round-off of a few hundred additions.
        EXPECT_NEAR(added, 9.2 * 2.5, 1e-12 * 23) << from << " → " << to;
        EXPECT_NEAR(sum(e), added, 1e-12 * 23);
        // Only cells the nut touched are heated.
        const double lo = std::min(from, to) - kNut / 2, hi = std::max(from, to) + kNut / 2;
        for (int i = 0; i < kCells; ++i)
            if ((i + 1) * kCell < lo || i * kCell > hi) {
                EXPECT_EQ(e[static_cast<std::size_t>(i)], 0) << "cell " << i;
            }
    }
}

// Centre moving uniformly from a to the end L: each metre of centre travel
// carries P·duration/(L − a) joules, of which the fraction (c + w/2 − L)/w is
// beyond the end once c > L − w/2. Lost:
// P·duration/((L − a) w) · ∫_{L−w/2}^{L} (c + w/2 − L) dc = P·duration·w / (8 (L − a)).
TEST(NutHeatDeposition, StrokeReachingTheEndLosesThePartBeyondIt) {
    const double L = kCells * kCell, a = 0.6, P = 9.2, duration = 2.25;
    const double lost = P * duration * kNut / (8 * (L - a));
    std::vector<double> e(kCells, 0.0);
    EXPECT_NEAR(depositNutHeat(e, kCell, kNut, a, L, duration, P), P * duration - lost,
                1e-12 * P * duration);
    // The same at the fixed end, moving from 0 towards +x.
    std::vector<double> f(kCells, 0.0);
    EXPECT_NEAR(depositNutHeat(f, kCell, kNut, 0.0, L - a, duration, P), P * duration - lost,
                1e-12 * P * duration);
    // A nut entirely past the end adds nothing.
    std::vector<double> g(kCells, 0.0);
    EXPECT_EQ(depositNutHeat(g, kCell, kNut, L + 0.05, L + 0.1, 1, P), 0);
    EXPECT_EQ(sum(g), 0);
}

TEST(NutHeatDeposition, CellEnergiesEqualTheTimeIntegralOfTheOverlap) {
    struct Stroke {
        double from, to, duration;
    };
    // Long and short strokes, aligned and unaligned to cell faces, and one
    // clipped at the end of the screw.
    for (Stroke s : {Stroke{0.1, 0.7, 4.5}, Stroke{0.4123, 0.4001, 0.1}, Stroke{0.315, 0.36, 1.0},
                     Stroke{0.85, 0.9, 0.4}}) {
        std::vector<double> exact(kCells, 0.0);
        depositNutHeat(exact, kCell, kNut, s.from, s.to, s.duration, 9.2);
        // The midpoint rule on a piecewise-quadratic integrand with kinks:
        // error per cell ≲ P·duration·(δc/w)² with δc = stroke/100 000.
        const auto reference = bruteForce(s.from, s.to, s.duration, 9.2, 100000);
        double worst = 0;
        for (std::size_t i = 0; i < exact.size(); ++i)
            worst = std::max(worst, std::abs(exact[i] - reference[i]));
        EXPECT_LT(worst, 1e-6 * 9.2 * s.duration) << s.from << " → " << s.to;
    }
}

TEST(NutHeatDeposition, DwellHeatsTheCellsUnderTheNut) {
    std::vector<double> e(kCells, 0.0);
    const double centre = 0.3021;  // the nut faces fall inside cells
    const double added = depositNutHeat(e, kCell, kNut, centre, centre, 10, 3);
    EXPECT_NEAR(added, 30, 1e-12 * 30);
    for (int i = 0; i < kCells; ++i) {
        const double overlap = std::max(0.0, std::min((i + 1) * kCell, centre + kNut / 2) -
                                                 std::max(i * kCell, centre - kNut / 2));
        EXPECT_NEAR(e[static_cast<std::size_t>(i)], 30 * overlap / kNut, 1e-12) << "cell " << i;
    }
    // Zero power or duration adds nothing.
    EXPECT_EQ(depositNutHeat(e, kCell, kNut, 0.2, 0.3, 0, 3), 0);
    EXPECT_EQ(depositNutHeat(e, kCell, kNut, 0.2, 0.3, 1, 0), 0);
}

TEST(NutHeatDeposition, MotionFromSamplesIsPiecewiseLinear) {
    const auto motion = motionFromPositionSamples({0, 0.1, 0.2, 0.3}, {100, 110, 110, 105});
    ASSERT_EQ(motion.size(), 3u);
    EXPECT_EQ(motion[0], (MotionSegment{0, 0.1, 100, 110, 6000}));
    EXPECT_TRUE(motion[1].isDwell());
    EXPECT_DOUBLE_EQ(motion[2].feed_mm_min, -3000);
    EXPECT_TRUE(motionFromPositionSamples({}, {}).empty());
    EXPECT_TRUE(motionFromPositionSamples({5}, {1}).empty());
}

/// A nut stroking 100 ↔ 300 mm at 6000 mm/min (2 s a stroke) for 600 s,
/// sampled as a logger would every `every_s` (its feed too, signed).
struct SampledStrokes {
    std::vector<double> time_s, position_mm, feed_mm_min;
    static constexpr double kPath_mm = 600 * 100.0;  // 100 mm/s for 600 s
    explicit SampledStrokes(double every_s) {
        for (double t = 0; t <= 600; t += every_s) {
            const double phase = std::fmod(t, 4.0);  // up for 2 s, down for 2 s
            time_s.push_back(t);
            position_mm.push_back(phase < 2 ? 100 + 100 * phase : 300 - 100 * (phase - 2));
            feed_mm_min.push_back(phase < 2 ? 6000 : -6000);
        }
    }
};

double pathOf(const std::vector<MotionSegment>& motion, double* below200_s = nullptr) {
    double path = 0;
    for (const MotionSegment& m : motion) {
        path += std::abs(m.to_mm - m.from_mm);
        // Time spent below 200 mm, for a stroke at constant speed.
        if (below200_s && m.to_mm != m.from_mm) {
            const double lo = std::min(m.from_mm, m.to_mm), hi = std::max(m.from_mm, m.to_mm);
            *below200_s += (m.end_s - m.start_s) * std::clamp((200 - lo) / (hi - lo), 0.0, 1.0);
        }
    }
    return path;
}

TEST(NutHeatDeposition, StrokesASparseLogMissesAreFilledInFromTheLoggedFeed) {
    // Every 7.3 s a logger sees one point of a 4 s back-and-forth: lines
    // through the points travel a fifth of the path, and would heat as little.
    const SampledStrokes log(7.3);
    const auto lines = motionFromPositionSamples(log.time_s, log.position_mm);
    EXPECT_LT(pathOf(lines), 0.3 * SampledStrokes::kPath_mm);
    // With the feed, the strokes between the positions logged nearby: the
    // whole path, in the range, half the time on either side of its middle,
    // and without a hole in time.
    const auto strokes =
        motionFromPositionSamples(log.time_s, log.position_mm, log.time_s, log.feed_mm_min);
    double below200_s = 0;
    EXPECT_NEAR(pathOf(strokes, &below200_s), SampledStrokes::kPath_mm,
                0.03 * SampledStrokes::kPath_mm);
    EXPECT_NEAR(below200_s / log.time_s.back(), 0.5, 0.05);
    for (std::size_t k = 0; k < strokes.size(); ++k) {
        const MotionSegment& m = strokes[k];
        EXPECT_GE(std::min(m.from_mm, m.to_mm), 100 - 1e-9);
        EXPECT_LE(std::max(m.from_mm, m.to_mm), 300 + 1e-9);
        EXPECT_NEAR(m.start_s, k == 0 ? 0 : strokes[k - 1].end_s, 1e-9);
    }
    EXPECT_NEAR(strokes.back().end_s, log.time_s.back(), 1e-9);
}

TEST(NutHeatDeposition, ADenseLogIsFollowedAsLoggedAndOnlyItsReversalsAreFilledIn) {
    // At 10 Hz the lines through the points cut the corners of the reversals
    // only; the feed restores them and adds nothing elsewhere.
    const SampledStrokes log(0.1);
    const auto lines = motionFromPositionSamples(log.time_s, log.position_mm);
    const auto strokes =
        motionFromPositionSamples(log.time_s, log.position_mm, log.time_s, log.feed_mm_min);
    EXPECT_NEAR(pathOf(lines), SampledStrokes::kPath_mm, 0.03 * SampledStrokes::kPath_mm);
    EXPECT_NEAR(pathOf(strokes), SampledStrokes::kPath_mm, 0.002 * SampledStrokes::kPath_mm);
    std::size_t same = 0;
    for (const MotionSegment& m : strokes)
        same += std::find(lines.begin(), lines.end(), m) != lines.end();
    EXPECT_GT(same, lines.size() * 9 / 10);
}

void expectThrowsMentioning(const std::vector<double>& t, const std::vector<double>& x,
                            const std::string& fragment) {
    try {
        motionFromPositionSamples(t, x);
        ADD_FAILURE() << "no exception, expected one mentioning " << fragment;
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
    }
}

TEST(NutHeatDeposition, MotionFromSamplesRejectsBrokenLogs) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expectThrowsMentioning({0, 1}, {1}, "differ in length");
    expectThrowsMentioning({0, 1, 1}, {1, 2, 3}, "does not increase at sample 2");
    expectThrowsMentioning({0, 2, 1}, {1, 2, 3}, "does not increase at sample 2");
    expectThrowsMentioning({0, 1, 2}, {1, nan, 3}, "missing position at sample 1");
    expectThrowsMentioning({0, 1, 2}, {nan, 2, 3}, "missing position at sample 0");
}

}  // namespace
}  // namespace driftlab::physics
