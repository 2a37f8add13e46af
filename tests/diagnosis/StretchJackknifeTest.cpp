// The statistics behind a diagnosis's confidence: Student's t against its
// tables, stretches of a run in time order, and the probability that one
// held-out gain beats another, checked for calibration where the truth is
// known (many draws of stretches whose true gains are equal, or differ), and
// the share of the structure a named cause explains, which scales its confidence.
#include <gtest/gtest.h>

#include <random>

#include "core/diagnosis/ResidualStructure.h"
#include "core/diagnosis/StretchJackknife.h"

using namespace driftlab;
using diagnosis::probabilityLarger;
using diagnosis::StretchSquares;

namespace {

/// Stretch sums of squares as a residual of RMS `before` and gain `gain`
/// leaves them: each stretch's mean square scattered as over `readings`
/// readings of Gaussian noise.
StretchSquares draw(std::mt19937& rng, int stretches, double gain, int readings = 30) {
    std::chi_squared_distribution<double> chi2(readings);
    StretchSquares s;
    for (int k = 0; k < stretches; ++k) {
        s.before.push_back(chi2(rng) / readings);
        s.after.push_back((1 - gain) * (1 - gain) * chi2(rng) / readings);
    }
    return s;
}

}  // namespace

TEST(StretchJackknife, studentTMatchesItsTable) {
    EXPECT_DOUBLE_EQ(diagnosis::studentTCdf(0, 5), 0.5);
    // Two-sided 95 % points: t(9) = 2.262, t(19) = 2.093, t(∞) = 1.960.
    EXPECT_NEAR(diagnosis::studentTCdf(2.262, 9), 0.975, 2e-4);
    EXPECT_NEAR(diagnosis::studentTCdf(-2.093, 19), 0.025, 2e-4);
    EXPECT_NEAR(diagnosis::studentTCdf(1.960, 1e7), 0.975, 2e-4);
    // One degree of freedom is Cauchy: 1/2 + atan(t)/π.
    EXPECT_NEAR(diagnosis::studentTCdf(3, 1), 0.5 + std::atan(3.0) / M_PI, 1e-12);
}

TEST(StretchJackknife, eachReadingCountsInTheStretchOfItsTime) {
    models::ReadingResiduals before, after;
    for (int i = 0; i <= 100; ++i) {
        before.points.push_back({double(i) * 36, 0});  // one hour
        before.error_um.push_back(i < 50 ? 1.0 : 2.0);
        after.points.push_back(before.points.back());
        after.error_um.push_back(0.5);
    }
    before.sensors.push_back({QStringLiteral("T_nut"), {}, {0, 3600}, {0.1, 0.3}});
    after.sensors.push_back({QStringLiteral("T_nut"), {}, {0, 3600}, {0.1, 0.1}});
    const StretchSquares positioning =
        diagnosis::stretchSquares({before, before}, {after, after}, QString(), 4);
    ASSERT_EQ(positioning.before.size(), 8u);
    // Readings 0–24 in the first quarter hour, 1 µm each; the last stretch
    // takes 75–100 (the end of the run is in it).
    EXPECT_DOUBLE_EQ(positioning.before[0], 25.0);
    EXPECT_DOUBLE_EQ(positioning.before[3], 26 * 4.0);
    EXPECT_DOUBLE_EQ(positioning.after[3], 26 * 0.25);
    EXPECT_DOUBLE_EQ(positioning.before[4], positioning.before[0]);  // the second run
    const StretchSquares sensor =
        diagnosis::stretchSquares({before}, {after}, QStringLiteral("T_nut"), 4);
    EXPECT_NEAR(sensor.before[0], 0.01, 1e-15);
    EXPECT_NEAR(sensor.before[3], 0.09, 1e-15);
    EXPECT_NEAR(sensor.after[3], 0.01, 1e-15);
    EXPECT_DOUBLE_EQ(sensor.before[1] + sensor.before[2], 0.0);
}

TEST(StretchJackknife, aGainClearlyAboveAnotherIsNearlyCertainAndEqualGainsAreEven) {
    std::mt19937 rng(7);
    const StretchSquares strong = draw(rng, 10, 0.8);
    const StretchSquares weak = draw(rng, 10, 0.2);
    EXPECT_GT(probabilityLarger(strong, &weak), 0.999);
    EXPECT_LT(probabilityLarger(weak, &strong), 0.001);
    EXPECT_GT(probabilityLarger(weak, nullptr), 0.99);
    EXPECT_DOUBLE_EQ(probabilityLarger(strong, &strong), 0.5);
    // No stretch with readings: nothing is known.
    EXPECT_DOUBLE_EQ(probabilityLarger(StretchSquares{}, nullptr), 0.5);
}

// What makes the probability worth its name: where two candidates are truly
// equally good, it is above 0.9 in about a tenth of the draws (a uniform
// p-value), not half of them; where one is truly better, it is high.
TEST(StretchJackknife, theProbabilityIsCalibratedWhereTheTruthIsKnown) {
    std::mt19937 rng(2026);
    const int draws = 4000;
    int above90 = 0, above50 = 0, betterFound = 0;
    for (int d = 0; d < draws; ++d) {
        const StretchSquares a = draw(rng, 20, 0.5), b = draw(rng, 20, 0.5);
        // The same stretches before: the two candidates start from one base.
        StretchSquares bOnSame = b;
        bOnSame.before = a.before;
        const double p = probabilityLarger(a, &bOnSame);
        above90 += p > 0.9;
        above50 += p > 0.5;
        StretchSquares better = draw(rng, 20, 0.55);
        better.before = a.before;
        betterFound += probabilityLarger(better, &bOnSame) > 0.9;
    }
    SCOPED_TRACE(::testing::Message()
                 << "equal gains: p > 0.9 in " << above90 << ", p > 0.5 in " << above50
                 << ", a better one found in " << betterFound << " of " << draws << " draws");
    EXPECT_NEAR(double(above90) / draws, 0.10, 0.025);
    EXPECT_NEAR(double(above50) / draws, 0.50, 0.04);
    EXPECT_GT(double(betterFound) / draws, 0.8);
}

TEST(StructureExplained, isTheShareOfTheMeanSquareAboveTheNoise) {
    // 2 µm RMS before, 1 µm reading noise: 3 µm² of structure. Leaving 1.5 µm
    // explains 4 − 2.25 = 1.75 µm² of it; leaving the noise explains all.
    diagnosis::ResidualSummary before, after;
    before.error_rms_um = 2;
    after.error_noise_um = 1;
    after.error_rms_um = 1.5;
    EXPECT_NEAR(diagnosis::structureExplained(before, after), 1.75 / 3, 1e-12);
    after.error_rms_um = 0.9;  // below the noise: nothing left to explain
    EXPECT_DOUBLE_EQ(diagnosis::structureExplained(before, after), 1);
    after.error_rms_um = 2.1;  // worse than the base model
    EXPECT_DOUBLE_EQ(diagnosis::structureExplained(before, after), 0);
    before.error_rms_um = 1.45;  // the base at noise level: a sensor's effect
    after.error_rms_um = 1.5;
    EXPECT_DOUBLE_EQ(diagnosis::structureExplained(before, after), 1);
}

TEST(StructureExplained, itsRmsIsReadWithTheNoiseTakenOutOfBeforeAndAfter) {
    // 0.63 µm RMS before, 0.33 µm reading noise, 0.34 µm left (the motor heat
    // of an independent campaign): 1 − after/before says 46 %, yet what is
    // left is the noise but 0.08 µm, and the structure's RMS (0.54 µm) is
    // 85 % gone.
    diagnosis::ResidualSummary before, after;
    before.error_rms_um = 0.63;
    after.error_noise_um = 0.33;
    after.error_rms_um = 0.34;
    const double structure = std::sqrt(0.63 * 0.63 - 0.33 * 0.33);
    const double left = std::sqrt(0.34 * 0.34 - 0.33 * 0.33);
    EXPECT_NEAR(diagnosis::structureRmsExplained(before, after), 1 - left / structure, 1e-12);
    EXPECT_NEAR(diagnosis::structureRmsExplained(before, after), 0.85, 0.01);
    // Far above the noise it is 1 − after/before.
    before.error_rms_um = 300;
    after.error_rms_um = 120;
    EXPECT_NEAR(diagnosis::structureRmsExplained(before, after), 0.6, 1e-5);
    after.error_rms_um = 0.2;  // below the noise: all of it
    EXPECT_DOUBLE_EQ(diagnosis::structureRmsExplained(before, after), 1);
    before.error_rms_um = 0.45;  // the base at noise level: no structure to read
    EXPECT_DOUBLE_EQ(diagnosis::structureRmsExplained(before, after), 0);
}
