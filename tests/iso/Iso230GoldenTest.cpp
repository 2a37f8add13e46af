// ISO 230-2 golden values worked by hand (Iso230TestData.h shows the
// arithmetic). The faults of the only public implementation we know are each
// pinned here: forward and backward swapped, x̄ divided by the number of
// targets, E's minimum with the wrong comparison, R without its bidirectional
// and backward terms.

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/iso/Iso230TestData.h"

namespace driftlab::iso {
namespace {

using test::add;
using test::golden3x5;

constexpr double kExact = 1e-12;

Evaluation evaluateOk(const std::vector<Reading>& readings, const Settings& settings = {}) {
    Evaluation e = evaluate(readings, settings);
    EXPECT_TRUE(e.ok()) << qPrintable(e.error);
    return e;
}

TEST(Iso230Golden, plusIsThePositiveApproach) {
    EXPECT_EQ(directionFromText(QStringLiteral("+")), Direction::Positive);
    EXPECT_EQ(directionFromText(QStringLiteral("-")), Direction::Negative);
    EXPECT_EQ(directionFromText(QStringLiteral(" + ")), Direction::Positive);
    // As interferometer packages write them.
    EXPECT_EQ(directionFromText(QStringLiteral("↑")), Direction::Positive);
    EXPECT_EQ(directionFromText(QStringLiteral("Down")), Direction::Negative);
    EXPECT_EQ(directionFromText(QStringLiteral("−")), Direction::Negative);  // U+2212
    EXPECT_EQ(directionFromText(QStringLiteral("+1")), Direction::Positive);
    EXPECT_EQ(directionFromText(QStringLiteral("1")), std::nullopt);
    EXPECT_EQ(directionFromText(QString()), std::nullopt);
    EXPECT_EQ(directionFromText(QStringLiteral("+-")), std::nullopt);
    // G1's '+' readings at 0 mm are 2, 4, 3, 4, 2: x̄↑ = 3, x̄↓ = −2, so
    // B_0 = x̄↑ − x̄↓ = +5; swapped directions would give −5 and E↑ = 7.
    const Evaluation e = evaluateOk(golden3x5());
    ASSERT_EQ(e.targets.size(), 3u);
    EXPECT_NEAR(e.targets[0].mean_up_um, 3, kExact);
    EXPECT_NEAR(e.targets[0].mean_down_um, -2, kExact);
    EXPECT_NEAR(e.targets[0].reversal_um, 5, kExact);
    EXPECT_NEAR(e.axis.reversal_um, 5, kExact);
    EXPECT_NEAR(e.axis.e_up_um, 5, kExact);
    EXPECT_NEAR(e.axis.e_down_um, 7, kExact);
}

TEST(Iso230Golden, meanDividesByCyclesNotTargets) {
    // G1, 0 mm ↑: (2 + 4 + 3 + 4 + 2) / 5 cycles = 3, not 15 / 3 targets = 5.
    const Evaluation e = evaluateOk(golden3x5());
    EXPECT_NEAR(e.targets[0].mean_up_um, 15.0 / 5, kExact);
    // Unequal counts: 10 mm ↑ 1, 2, 3, 6 → 12 / 4 = 3; ↓ 0, 2, 4 → 6 / 3 = 2;
    // 20 mm ↑ 5, 7 → 6; ↓ 1, 3 → 2. Two targets: a division by 2 would give
    // 6, 3, 6, 2.
    std::vector<Reading> r;
    add(r, 10, Direction::Positive, {1, 2, 3, 6});
    add(r, 10, Direction::Negative, {0, 2, 4});
    add(r, 20, Direction::Positive, {5, 7});
    add(r, 20, Direction::Negative, {1, 3});
    const Evaluation u = evaluateOk(r);
    EXPECT_NEAR(u.targets[0].mean_up_um, 3, kExact);
    EXPECT_NEAR(u.targets[0].mean_down_um, 2, kExact);
    EXPECT_NEAR(u.targets[1].mean_up_um, 6, kExact);
    EXPECT_NEAR(u.targets[1].mean_down_um, 2, kExact);
    EXPECT_EQ(u.targets[0].n_up, 4);
    EXPECT_EQ(u.targets[0].n_down, 3);
}

TEST(Iso230Golden, systematicErrorSpansTheMeansOfBothDirections) {
    // ↑ means 3, 4, −1; ↓ means −2, 3, −4. E = 4 (↑ at 100 mm) − (−4) (↓ at
    // 200 mm) = 8, larger than E↑ = 5 and E↓ = 7.
    const Evaluation e = evaluateOk(golden3x5());
    EXPECT_NEAR(e.axis.e_um, 8, kExact);
    EXPECT_NE(e.axis.e_um, e.axis.e_up_um);
    EXPECT_NE(e.axis.e_um, e.axis.e_down_um);
    EXPECT_NEAR(e.axis.e_up_um, 5, kExact);
    EXPECT_NEAR(e.axis.e_down_um, 7, kExact);
}

TEST(Iso230Golden, repeatabilityTakesBidirectionalAndBackwardTerms) {
    const Evaluation e = evaluateOk(golden3x5());
    // 0 mm: 2s↑ + 2s↓ + |B| = 2 + 2 + 5 = 9 beats R↑_i = R↓_i = 4.
    EXPECT_NEAR(e.targets[0].r_up_um, 4, kExact);
    EXPECT_NEAR(e.targets[0].r_down_um, 4, kExact);
    EXPECT_NEAR(e.targets[0].r_um, 9, kExact);
    // 100 mm: the backward R↓_i = 4 · 1.5 = 6 beats 1 + 3 + 1 = 5 and R↑_i = 2.
    EXPECT_NEAR(e.targets[1].r_um, 6, kExact);
    EXPECT_NEAR(e.targets[1].r_down_um, 6, kExact);
    // 200 mm: 0 + 2 + 3 = 5 beats R↓_i = 4.
    EXPECT_NEAR(e.targets[2].r_um, 5, kExact);
    // Axis: R = 9, not max(R↑, R↓) = 6 and not R↑ = 4.
    EXPECT_NEAR(e.axis.r_up_um, 4, kExact);
    EXPECT_NEAR(e.axis.r_down_um, 6, kExact);
    EXPECT_NEAR(e.axis.r_um, 9, kExact);
}

TEST(Iso230Golden, perTargetValuesWorkedByHand) {
    const Evaluation e = evaluateOk(golden3x5());
    ASSERT_EQ(e.targets.size(), 3u);
    struct Expected {
        double target, up, down, sUp, sDown, b, rUp, rDown, r, mean;
    };
    const Expected expected[] = {{0, 3, -2, 1, 1, 5, 4, 4, 9, 0.5},
                                 {100, 4, 3, 0.5, 1.5, 1, 2, 6, 6, 3.5},
                                 {200, -1, -4, 0, 1, 3, 0, 4, 5, -2.5}};
    for (int i = 0; i < 3; ++i) {
        const TargetResult& t = e.targets[i];
        const Expected& x = expected[i];
        SCOPED_TRACE(t.target_mm);
        EXPECT_EQ(t.target_mm, x.target);
        EXPECT_EQ(t.n_up, 5);
        EXPECT_EQ(t.n_down, 5);
        EXPECT_NEAR(t.mean_up_um, x.up, kExact);
        EXPECT_NEAR(t.mean_down_um, x.down, kExact);
        EXPECT_NEAR(t.s_up_um, x.sUp, kExact);
        EXPECT_NEAR(t.s_down_um, x.sDown, kExact);
        EXPECT_NEAR(t.reversal_um, x.b, kExact);
        EXPECT_NEAR(t.r_up_um, x.rUp, kExact);
        EXPECT_NEAR(t.r_down_um, x.rDown, kExact);
        EXPECT_NEAR(t.r_um, x.r, kExact);
        EXPECT_NEAR(t.mean_um, x.mean, kExact);
    }
    EXPECT_EQ(e.cycles, 5);
    // Every target reads low in cycles 1 and 5 and high in 2 and 4: a swing
    // common to the whole axis, per-cycle means −5/6, 5/6, 0, 5/6, −5/6 µm,
    // spanning 5/3 µm, twice the mean s of 5/6 µm. No trend, but not scatter.
    // Three targets over 200 mm are below the standard's five; the values are
    // still determined, and the shortfall is named first.
    ASSERT_EQ(e.warnings.size(), 2);
    EXPECT_EQ(e.warnings.front(),
              QStringLiteral("below ISO 230-2's minimum: 3 targets over 200 mm; at least 5 are "
                             "needed (five, and five per metre)"));
    EXPECT_EQ(e.warnings.back(),
              QStringLiteral("deviations drift from cycle to cycle: the per-cycle mean deviation "
                             "spans 1.67 µm (lowest in cycle 1, highest in cycle 2; linear trend "
                             "0.000 µm per cycle), more than the mean standard deviation 0.83 µm; "
                             "non-stationary data (e.g. thermal drift) inflate R and A"));
    EXPECT_TRUE(e.skipped.isEmpty());
}

TEST(Iso230Golden, axisValuesWorkedByHand) {
    const AxisResult a = evaluateOk(golden3x5()).axis;
    EXPECT_NEAR(a.reversal_um, 5, kExact);
    EXPECT_NEAR(a.mean_reversal_um, 3, kExact);
    EXPECT_NEAR(a.r_up_um, 4, kExact);
    EXPECT_NEAR(a.r_down_um, 6, kExact);
    EXPECT_NEAR(a.r_um, 9, kExact);
    EXPECT_NEAR(a.e_up_um, 5, kExact);
    EXPECT_NEAR(a.e_down_um, 7, kExact);
    EXPECT_NEAR(a.e_um, 8, kExact);
    EXPECT_NEAR(a.m_um, 6, kExact);
    EXPECT_NEAR(a.a_up_um, 6, kExact);
    EXPECT_NEAR(a.a_down_um, 12, kExact);
    EXPECT_NEAR(a.a_um, 12, kExact);
}

TEST(Iso230Golden, reversalErrorIsTheLargestMagnitudeAndItsMeanKeepsTheSigns) {
    // B_i = −6, +2, +1: B = max |B_i| = 6 (not +2, the largest signed value); B̄ = −1.
    std::vector<Reading> r;
    add(r, 0, Direction::Positive, {0, 0});
    add(r, 0, Direction::Negative, {6, 6});
    add(r, 50, Direction::Positive, {2, 2});
    add(r, 50, Direction::Negative, {0, 0});
    add(r, 100, Direction::Positive, {1, 1});
    add(r, 100, Direction::Negative, {0, 0});
    const Evaluation e = evaluateOk(r);
    EXPECT_NEAR(e.axis.reversal_um, 6, kExact);
    EXPECT_NEAR(e.axis.mean_reversal_um, -1, kExact);
}

TEST(Iso230Golden, targetsAreSortedAscendingWhateverTheReadingOrder) {
    std::vector<Reading> shuffled = golden3x5();
    std::reverse(shuffled.begin(), shuffled.end());
    const Evaluation e = evaluateOk(shuffled);
    ASSERT_EQ(e.targets.size(), 3u);
    EXPECT_EQ(e.targets[0].target_mm, 0);
    EXPECT_EQ(e.targets[1].target_mm, 100);
    EXPECT_EQ(e.targets[2].target_mm, 200);
    EXPECT_NEAR(e.axis.r_um, 9, kExact);
    EXPECT_NEAR(e.axis.a_um, 12, kExact);
}

TEST(Iso230Golden, coverageFactorScalesTheExpandedQuantities) {
    // k = 3: R↑_i = 6s↑, R_i = 3s↑ + 3s↓ + |B_i|, A with x̄ ± 3s.
    //   0 mm: R↑ = R↓ = 6, R = 3 + 3 + 5 = 11; 100 mm: R↑ = 3, R↓ = 9,
    //   R = max(1.5 + 4.5 + 1, 3, 9) = 9; 200 mm: R↓ = 6, R = 0 + 3 + 3 = 6.
    //   A↑ = max(6, 5.5, −1) − min(0, 2.5, −1) = 7;
    //   A↓ = max(1, 7.5, −1) − min(−5, −1.5, −7) = 14.5; A = 7.5 − (−7) = 14.5.
    Settings settings;
    settings.coverage_factor = 3;
    const Evaluation e = evaluateOk(golden3x5(), settings);
    EXPECT_NEAR(e.targets[0].r_up_um, 6, kExact);
    EXPECT_NEAR(e.targets[0].r_um, 11, kExact);
    EXPECT_NEAR(e.targets[1].r_um, 9, kExact);
    EXPECT_NEAR(e.targets[2].r_um, 6, kExact);
    EXPECT_NEAR(e.axis.r_um, 11, kExact);
    EXPECT_NEAR(e.axis.a_up_um, 7, kExact);
    EXPECT_NEAR(e.axis.a_down_um, 14.5, kExact);
    EXPECT_NEAR(e.axis.a_um, 14.5, kExact);
    // Values without s do not depend on k.
    EXPECT_NEAR(e.axis.e_um, 8, kExact);
    EXPECT_NEAR(e.axis.m_um, 6, kExact);
    EXPECT_EQ(e.settings.coverage_factor, 3);
}

TEST(Iso230Golden, editionsAreNamedAndComputeAlike) {
    // No calculation difference between 1997, 2006 and 2014 could be
    // confirmed from public sources (docs/iso230.md): the edition is named.
    for (const auto& [year, edition] : {std::pair{QStringLiteral("1997"), Edition::Iso1997},
                                        std::pair{QStringLiteral("2006"), Edition::Iso2006},
                                        std::pair{QStringLiteral("2014"), Edition::Iso2014}}) {
        EXPECT_EQ(editionFromString(year), edition);
        EXPECT_EQ(toString(edition), QStringLiteral("ISO 230-2:") + year);
        Settings settings;
        settings.edition = edition;
        const Evaluation e = evaluateOk(golden3x5(), settings);
        EXPECT_EQ(e.settings.edition, edition);
        EXPECT_NEAR(e.axis.r_um, 9, kExact);
        EXPECT_NEAR(e.axis.a_um, 12, kExact);
    }
    EXPECT_EQ(editionFromString(QStringLiteral("1988")), std::nullopt);
}

}  // namespace
}  // namespace driftlab::iso
