// ISO 230-2 input that cannot be evaluated (refused, naming the target and
// direction), the long-axis rule that skips what the standard skips, and the
// warnings: drift from cycle to cycle and repeated readings.

#include <gtest/gtest.h>

#include "tests/iso/Iso230TestData.h"

namespace driftlab::iso {
namespace {

using test::add;
using test::golden3x5;
using test::longAxisSingleApproach;
using test::withoutMinimums;

constexpr double kRoundOffUm = 1e-12;

TEST(Iso230Validation, singleReadingOnShortAxisIsRefusedNamingTargetAndDirection) {
    std::vector<Reading> r = golden3x5();
    // Keep one ↓ reading at 100 mm.
    std::erase_if(r, [](const Reading& x) {
        return x.target_mm == 100 && x.direction == Direction::Negative && x.cycle > 1;
    });
    const Evaluation e = evaluate(r);
    EXPECT_FALSE(e.ok());
    EXPECT_EQ(e.error,
              QStringLiteral("target 100 mm, direction - (↓): 1 reading, the standard deviation "
                             "s needs at least 2 (ISO 230-2 allows one approach per direction "
                             "only on axes over 2000 mm; this travel is 200 mm)"));
}

TEST(Iso230Validation, targetWithoutOneDirectionIsRefused) {
    std::vector<Reading> r = golden3x5();
    std::erase_if(r, [](const Reading& x) {
        return x.target_mm == 200 && x.direction == Direction::Positive;
    });
    const Evaluation e = evaluate(r);
    EXPECT_EQ(e.error, QStringLiteral("target 200 mm, direction + (↑): no reading; ISO 230-2 "
                                      "needs both approaches at every target"));
}

TEST(Iso230Validation, noReadingsAndBadSettingsAreRefused) {
    EXPECT_EQ(evaluate({}).error, QStringLiteral("no readings to evaluate"));
    Settings settings;
    settings.coverage_factor = 0;
    EXPECT_FALSE(evaluate(golden3x5(), settings).ok());
    EXPECT_TRUE(evaluate(golden3x5(), settings).error.contains(QStringLiteral("coverage factor")));
    std::vector<Reading> r = golden3x5();
    r[3].deviation_um = std::numeric_limits<double>::infinity();
    EXPECT_EQ(evaluate(r).error,
              QStringLiteral("reading 4: target or deviation is not a finite number"));
}

TEST(Iso230Validation, longAxisWithOneApproachSkipsTheValuesThatNeedS) {
    const Evaluation e = evaluate(longAxisSingleApproach());
    ASSERT_TRUE(e.ok()) << qPrintable(e.error);
    ASSERT_EQ(e.skipped.size(), 1);
    EXPECT_TRUE(e.skipped.front().startsWith(
        QStringLiteral("s↑_i, s↓_i, R↑_i, R↓_i, R_i, R↑, R↓, R, A↑, A↓, A not determined: "
                       "target 0 mm, direction + (↑) has one reading")))
        << qPrintable(e.skipped.front());
    EXPECT_TRUE(e.skipped.front().contains(QStringLiteral("this travel is 2500 mm")));
    // Hand values (Iso230TestData.h, G2).
    EXPECT_NEAR(e.axis.reversal_um, 2, kRoundOffUm);
    EXPECT_NEAR(e.axis.mean_reversal_um, 1, kRoundOffUm);
    EXPECT_NEAR(e.axis.e_up_um, 3, kRoundOffUm);
    EXPECT_NEAR(e.axis.e_down_um, 5, kRoundOffUm);
    EXPECT_NEAR(e.axis.e_um, 5, kRoundOffUm);
    EXPECT_NEAR(e.axis.m_um, 3.5, kRoundOffUm);
    EXPECT_NEAR(e.targets[1].reversal_um, -1, kRoundOffUm);
    for (double skipped :
         {e.axis.r_um, e.axis.r_up_um, e.axis.r_down_um, e.axis.a_um, e.axis.a_up_um,
          e.axis.a_down_um, e.targets[0].s_up_um, e.targets[0].r_um})
        EXPECT_TRUE(std::isnan(skipped));
}

TEST(Iso230Validation, driftFromCycleToCycleIsWarnedWithItsNumbers) {
    // Both targets, both directions: 0, 1, 2, 3, 4 µm over cycles 1..5. Every
    // x̄ = 2 and s = sqrt((4 + 1 + 0 + 1 + 4) / 4) = sqrt(2.5) = 1.58; the
    // per-cycle mean residual is −2, −1, 0, 1, 2: a trend of 1 µm per cycle,
    // 4 µm over the run, more than the mean s.
    std::vector<Reading> r;
    for (double target : {0.0, 100.0})
        for (Direction d : {Direction::Positive, Direction::Negative})
            add(r, target, d, {0, 1, 2, 3, 4});
    const Evaluation e = evaluate(r);
    ASSERT_TRUE(e.ok()) << qPrintable(e.error);
    EXPECT_NEAR(e.targets[0].s_up_um, std::sqrt(2.5), kRoundOffUm);
    const QStringList warnings = withoutMinimums(e.warnings);
    ASSERT_EQ(warnings.size(), 1);
    EXPECT_EQ(warnings.front(),
              QStringLiteral("deviations drift from cycle to cycle: the per-cycle mean deviation "
                             "spans 4.00 µm (lowest in cycle 1, highest in cycle 5; linear trend "
                             "1.000 µm per cycle), more than the mean standard deviation 1.58 µm; "
                             "non-stationary data (e.g. thermal drift) inflate R and A"));
}

TEST(Iso230Validation, driftThatRisesAndFallsIsWarnedThoughItsTrendIsFlat) {
    // A warm-up then a cool-down: 0, 2, 4, 2, 0 µm over cycles 1..5. x̄ = 1.6,
    // residuals −1.6, 0.4, 2.4, 0.4, −1.6: a straight line through them is flat
    // (trend 0), but they span 4 µm, more than s = sqrt(8.8 / 4) = 1.48 µm.
    std::vector<Reading> r;
    for (double target : {0.0, 100.0})
        for (Direction d : {Direction::Positive, Direction::Negative})
            add(r, target, d, {0, 2, 4, 2, 0});
    const Evaluation e = evaluate(r);
    ASSERT_TRUE(e.ok()) << qPrintable(e.error);
    const QStringList warnings = withoutMinimums(e.warnings);
    ASSERT_EQ(warnings.size(), 1);
    EXPECT_TRUE(warnings.front().startsWith(
        QStringLiteral("deviations drift from cycle to cycle: the per-cycle mean deviation spans "
                       "4.00 µm (lowest in cycle 1, highest in cycle 3; linear trend 0.000 µm")))
        << qPrintable(warnings.front());
}

TEST(Iso230Validation, stationaryScatterIsNotCalledDrift) {
    // Scatter of ±1 µm that no cycle shares across the axis: target 0 reads
    // −1, +1, 0, +1, −1 and target 100 the opposite, so every per-cycle mean
    // is 0 although s = 1 µm at every target.
    std::vector<Reading> r;
    for (Direction d : {Direction::Positive, Direction::Negative}) {
        add(r, 0, d, {-1, 1, 0, 1, -1});
        add(r, 100, d, {1, -1, 0, -1, 1});
    }
    const Evaluation e = evaluate(r);
    ASSERT_TRUE(e.ok()) << qPrintable(e.error);
    EXPECT_NEAR(e.targets[0].s_up_um, 1, kRoundOffUm);
    EXPECT_TRUE(withoutMinimums(e.warnings).isEmpty()) << qPrintable(e.warnings.join('\n'));
}

TEST(Iso230Validation, repeatedReadingOfOneCycleIsWarned) {
    std::vector<Reading> r = golden3x5();
    r.push_back({0, Direction::Positive, 2, 4});
    const Evaluation e = evaluate(r);
    ASSERT_TRUE(e.ok());
    EXPECT_TRUE(e.warnings.contains(
        QStringLiteral("target 0 mm, direction + (↑), cycle 2: 2 readings; each is counted as "
                       "an approach of its own")))
        << qPrintable(e.warnings.join('\n'));
    EXPECT_EQ(e.targets[0].n_up, 6);
}

TEST(Iso230Validation, targetsWithinTheToleranceAreOneTarget) {
    std::vector<Reading> r = golden3x5();
    for (Reading& x : r)
        if (x.target_mm == 100 && x.cycle == 3) x.target_mm = 100 + 1e-9;
    const Evaluation e = evaluate(r);
    ASSERT_TRUE(e.ok()) << qPrintable(e.error);
    EXPECT_EQ(e.targets.size(), 3u);
    EXPECT_NEAR(e.axis.r_um, 9, kRoundOffUm);
}

}  // namespace
}  // namespace driftlab::iso
