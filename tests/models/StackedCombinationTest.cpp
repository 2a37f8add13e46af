// `auto`'s stacking rule on hand-made held-out predictions: the weights of a
// case worked by hand, the simplex (weights ≥ 0 summing to one, and no point
// of it better), a copy of a family taking no weight, the stack against the
// mean of the near-best families, and the no-harm guard.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/models/StackedCombination.h"

namespace driftlab::models {
namespace {

/// Held-out predictions of one family on readings `measured`, one part.
HeldOutPredictions heldOut(const std::vector<double>& measured,
                           const std::vector<double>& predicted) {
    HeldOutPredictions p;
    p.measured_um = measured;
    p.predicted_um = predicted;
    p.position_mm.assign(measured.size(), 0.0);
    p.part_ends = {measured.size()};
    return p;
}

Eigen::MatrixXd columns(const std::vector<std::vector<double>>& families) {
    Eigen::MatrixXd P(Eigen::Index(families.front().size()), Eigen::Index(families.size()));
    for (std::size_t f = 0; f < families.size(); ++f)
        for (std::size_t i = 0; i < families[f].size(); ++i)
            P(Eigen::Index(i), Eigen::Index(f)) = families[f][i];
    return P;
}

// Two readings y = (2, 1); family 1 predicts (4, 1), family 2 (0, −1). Their
// combination w·p1 + (1 − w)·p2 = (4w, 2w − 1) misses by (4w − 2, 2w − 2),
// whose squares sum to 20w² − 24w + 8: least at w = 24/40 = 0.6. A third
// family (10, −10) is worse in the direction the other two leave: its
// gradient p3·r = 12 at the optimum's residual r = (0.4, −0.8), above the
// others' 0.8, so it takes none.
const std::vector<double> kMeasured{2, 1};
const std::vector<double> kFirst{4, 1}, kSecond{0, -1}, kThird{10, -10};

TEST(Stacking, findsTheWeightsOfACaseWorkedByHand) {
    const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(kMeasured.data(), 2);
    const Eigen::VectorXd w = stackingWeights(columns({kFirst, kSecond, kThird}), y);
    ASSERT_EQ(w.size(), 3);
    EXPECT_NEAR(w[0], 0.6, 1e-12);
    EXPECT_NEAR(w[1], 0.4, 1e-12);
    EXPECT_EQ(w[2], 0.0);
}

TEST(Stacking, aCopyOfAFamilyTakesNoWeight) {
    // The copy's gradient equals its original's: it cannot lower the error,
    // so it stays out, and the combination is the one without it.
    const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(kMeasured.data(), 2);
    const Eigen::VectorXd w = stackingWeights(columns({kFirst, kSecond, kFirst, kSecond}), y);
    EXPECT_NEAR(w[0], 0.6, 1e-12);
    EXPECT_NEAR(w[1], 0.4, 1e-12);
    EXPECT_EQ(w[2], 0.0);
    EXPECT_EQ(w[3], 0.0);
}

TEST(Stacking, aFamilyBestAloneTakesAllTheWeight) {
    // The others only add error: the best vertex of the simplex is optimal.
    const std::vector<double> y{1, 2, 3};
    const Eigen::VectorXd w = stackingWeights(columns({{1.1, 2.1, 3.1}, {3, 4, 5}, {2, 3, 4}}),
                                              Eigen::Map<const Eigen::VectorXd>(y.data(), 3));
    EXPECT_EQ(w[0], 1.0);
    EXPECT_EQ(w[1], 0.0);
    EXPECT_EQ(w[2], 0.0);
}

TEST(Stacking, weightsAreNonNegativeSumToOneAndNoPointOfTheSimplexIsBetter) {
    std::mt19937 random(7);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform(0, 1);
    for (int trial = 0; trial < 20; ++trial) {
        // Six families: the truth plus noise, scaled and shifted, and copies.
        const Eigen::Index rows = 60, families = 6;
        Eigen::VectorXd y(rows);
        for (Eigen::Index i = 0; i < rows; ++i) y[i] = std::sin(0.1 * double(i)) * 5;
        Eigen::MatrixXd P(rows, families);
        for (Eigen::Index f = 0; f < families; ++f)
            for (Eigen::Index i = 0; i < rows; ++i)
                P(i, f) = (0.5 + uniform(random)) * y[i] + normal(random) + 0.3 * double(f - 2);
        P.col(5) = P.col(trial % 5);
        const Eigen::VectorXd w = stackingWeights(P, y);
        EXPECT_GE(w.minCoeff(), 0.0) << trial;
        EXPECT_NEAR(w.sum(), 1.0, 1e-12) << trial;
        const double best = (P * w - y).squaredNorm();
        for (int k = 0; k < 2000; ++k) {
            Eigen::VectorXd v(families);
            for (Eigen::Index f = 0; f < families; ++f) v[f] = -std::log(uniform(random));
            v /= v.sum();
            ASSERT_LE(best, (P * v - y).squaredNorm() * (1 + 1e-12)) << trial;
        }
    }
}

const std::vector<bool> kEveryFamilyInTheMean(3, true);

TEST(Stacking, theStackIsChosenWhereItBeatsTheMeanOfTheNearBest) {
    // The near-best alone is family 1 (RMS √2 against 2 and 12): the stack's
    // √0.4 is far below it.
    const CombinationChoice choice = chooseCombination(
        {heldOut(kMeasured, kFirst), heldOut(kMeasured, kSecond), heldOut(kMeasured, kThird)},
        kEveryFamilyInTheMean);
    EXPECT_EQ(choice.kind, CombinationChoice::Kind::Stacked);
    ASSERT_EQ(choice.members, (std::vector<std::size_t>{0, 1}));  // heaviest first
    EXPECT_NEAR(choice.weights[0], 0.6, 1e-12);
    EXPECT_NEAR(choice.weights[1], 0.4, 1e-12);
    // Its held-out predictions are the weighted sum: (2.4, 0.2).
    EXPECT_NEAR(choice.predictions.predicted_um[0], 2.4, 1e-12);
    EXPECT_NEAR(choice.predictions.predicted_um[1], 0.2, 1e-12);
    EXPECT_NEAR(choice.stack_rms_um, std::sqrt((0.16 + 0.64) / 2), 1e-12);
    EXPECT_NEAR(choice.mean_rms_um, std::sqrt(2.0), 1e-12);
}

TEST(Stacking, theMeanOfTheNearBestIsKeptWhereTheStackGainsLessThanTwoPerCent) {
    // Two families off by +0.1 and −0.1 µm throughout: both within one
    // standard error of each other, and their mean exact, as the stack's
    // 0.5 + 0.5 is; the simpler combination is kept.
    const std::vector<double> y{1, -1, 1, -1};
    const CombinationChoice choice = chooseCombination(
        {heldOut(y, {1.1, -0.9, 1.1, -0.9}), heldOut(y, {0.9, -1.1, 0.9, -1.1})}, {true, true});
    EXPECT_EQ(choice.kind, CombinationChoice::Kind::Mean);
    EXPECT_EQ(choice.members.size(), 2u);
    EXPECT_EQ(choice.weights, (std::vector<double>{0.5, 0.5}));
    EXPECT_NEAR(choice.stack_weights[0], 0.5, 1e-12);
    EXPECT_NEAR(choice.predictions.rms_um(), 0, 1e-12);
}

TEST(Stacking, aFamilyOutOfTheMeanTakesPartThroughTheStackOnly) {
    // Family 2 may not join the mean: the mean is family 1 alone, which the
    // stack of both beats.
    const CombinationChoice choice =
        chooseCombination({heldOut(kMeasured, kFirst), heldOut(kMeasured, kSecond)}, {true, false});
    EXPECT_EQ(choice.kind, CombinationChoice::Kind::Stacked);
    EXPECT_NEAR(choice.mean_rms_um, std::sqrt(2.0), 1e-12);
    EXPECT_EQ(choice.members, (std::vector<std::size_t>{0, 1}));
}

TEST(Stacking, fallsBackToNoCompensationWhereNothingDoesBetter) {
    // Every family, and so every combination of them, misses y = (1, −1) by
    // more than predicting zero does: (3, 3) and (−3, 2) against |y| = √2.
    const std::vector<double> y{1, -1};
    const CombinationChoice choice =
        chooseCombination({heldOut(y, {3, 3}), heldOut(y, {-3, 2})}, {true, true});
    EXPECT_EQ(choice.kind, CombinationChoice::Kind::None);
    EXPECT_TRUE(choice.members.empty());
    EXPECT_TRUE(choice.weights.empty());
    EXPECT_EQ(choice.predictions.predicted_um, (std::vector<double>{0, 0}));
    EXPECT_DOUBLE_EQ(choice.predictions.rms_um(), choice.predictions.none_rms_um());
}

}  // namespace
}  // namespace driftlab::models
