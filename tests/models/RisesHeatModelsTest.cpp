// The shrunken all-rises families of a spindle's drift (`lsall-heat`,
// `ridge-heat`, `pcr-heat`) against known answers: the rotor campaign's heat
// that no thermometer sees, the penalty of ridge regression worked by hand and
// spread over thermometers that read one temperature, the number of patterns
// thermometers move in, and the refusal of a positioning error.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <random>

#include "core/models/AllRisesHeatModel.h"
#include "core/models/ModelScore.h"
#include "core/models/PrincipalRisesHeatModel.h"
#include "core/models/RidgeHeatModel.h"
#include "tests/models/ModelTestSupport.h"
#include "tests/models/SpindleTestCampaigns.h"
#include "tests/support/LeastSquaresBaselines.h"

namespace driftlab::models {
namespace {

const QString kZ = QStringLiteral("D_z");
constexpr double kPatternRun_s = 7200;

std::vector<std::unique_ptr<ThermalErrorModel>> everyFamily() {
    std::vector<std::unique_ptr<ThermalErrorModel>> families;
    families.push_back(std::make_unique<AllRisesHeatModel>());
    families.push_back(std::make_unique<RidgeHeatModel>());
    families.push_back(std::make_unique<PrincipalRisesHeatModel>());
    return families;
}

TEST(RisesHeat, everyFamilyGivesTheHeatOfAnUnsensedRotorThroughTheLaggedSpeedSquared) {
    // Four thermometers follow the bearings (∝ n); the rotor's own n² losses
    // through 900 s reach none of them. Noise-free: each family takes the
    // speed² within one step of the ×1.5 grid, its gain, and the bearings'
    // gains, and follows SP4, which goes to 9000 rpm beyond every training run.
    const Campaign c = test::rotorCampaign();
    const auto train = test::driftDataset(c, {"SP1", "SP2", "SP3"}, kZ);
    const auto heldOut = test::driftDataset(c, {"SP4"}, kZ);
    const test::LeastSquaresBaselines baselines = test::leastSquaresBaselines(train, heldOut);
    for (const auto& model : everyFamily()) {
        SCOPED_TRACE(qPrintable(model->name()));
        const FitSummary fit = model->fit(train);
        ASSERT_TRUE(fit.success) << qPrintable(fit.message);
        ASSERT_TRUE(fit.parameters.count(QStringLiteral("speed².tau")))
            << qPrintable(fit.notes.join(QStringLiteral(" | ")));
        const double tau = fit.parameters.at(QStringLiteral("speed².tau")).value;
        EXPECT_LT(std::abs(std::log(tau / test::kRotorLag_s)), std::log(1.5)) << tau;
        EXPECT_NEAR(fit.parameters.at(QStringLiteral("speed².a_lag")).value,
                    test::kRotorGain_um_per_krpm2, 0.01);
        for (std::size_t k = 0; k < 4; ++k)
            EXPECT_NEAR(fit.parameters.at(QStringLiteral("T%1.a").arg(k + 1)).value,
                        test::kBearingGain_um_per_K[k], 0.15)
                << k;
        const Score score = scoreModel(*model, heldOut);
        ASSERT_TRUE(score.ok()) << qPrintable(score.error);
        EXPECT_LT(score.rms_um, 0.03 * score.uncompensated_rms_um);
        EXPECT_LT(score.rms_um, 0.2 * baselines.all_rises.rms_um);
    }
}

TEST(RisesHeat, everyFamilyRefusesAPositioningError) {
    const DatasetResult train = buildDataset(test::twoSensorCampaign(2, {}), {"S1", "S2"});
    ASSERT_TRUE(train.ok()) << qPrintable(train.error);
    for (const auto& model : everyFamily()) {
        const FitSummary fit = model->fit(train.runs);
        EXPECT_FALSE(fit.success) << qPrintable(model->name());
        EXPECT_EQ(fit.message, QStringLiteral("model '%1' predicts a spindle's drift channel (its "
                                              "heat is the spindle speed), not a positioning "
                                              "error")
                                   .arg(model->name()));
    }
}

TEST(RidgeHeat, shrinksOnlyThePenalisedGainWhateverItsUnit) {
    // y = 1 + 2·x over x = (1, −1, 1, −1), ones beside it (both of RMS 1):
    // XᵀX = diag(4, 4), Xᵀy = (8, 4). With λ = 0.25 on four rows the slope's
    // diagonal takes λ·4 = 1: slope 8/5 = 1.6, the offset 4/4 = 1 untouched.
    // The same column in other units (x·10) is shrunk alike: slope 0.16.
    Eigen::MatrixXd X(4, 2);
    X << 1, 1, -1, 1, 1, 1, -1, 1;
    const Eigen::VectorXd y = Eigen::Vector4d(3, -1, 3, -1);
    Eigen::VectorXd b = ridgeSolve(X.transpose() * X, X.transpose() * y, 4, 0.25, 1);
    ASSERT_EQ(b.size(), 2);
    EXPECT_NEAR(b[0], 1.6, 1e-12);
    EXPECT_NEAR(b[1], 1.0, 1e-12);
    X.col(0) *= 10;
    b = ridgeSolve(X.transpose() * X, X.transpose() * y, 4, 0.25, 1);
    EXPECT_NEAR(b[0], 0.16, 1e-12);
    EXPECT_NEAR(b[1], 1.0, 1e-12);
    // λ = 0 is least squares; on a copied column it is singular.
    EXPECT_NEAR(ridgeSolve(X.transpose() * X, X.transpose() * y, 4, 0, 1)[0], 0.2, 1e-12);
    Eigen::MatrixXd copied(4, 2);
    copied << X.col(0), X.col(0);
    EXPECT_EQ(ridgeSolve(copied.transpose() * copied, copied.transpose() * y, 4, 0, 2).size(), 0);
}

/// White noise of standard deviation `sd_K`, one value per 15 s sample.
test::Profile whiteNoise(unsigned seed, double sd_K) {
    auto values = std::make_shared<std::vector<double>>();
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal(0.0, sd_K);
    for (double t = 0; t <= kPatternRun_s + 15; t += 15) values->push_back(normal(rng));
    return [values](double t) { return (*values)[std::size_t(std::lround(t / 15))]; };
}

/// A thermometer's own slow wander (a random walk of `step_K` per 15 s).
test::Profile wander(unsigned seed, double step_K) {
    const test::Profile walk = test::randomWalk(seed, step_K, 15, kPatternRun_s + 15);
    return [walk](double t) { return walk(t) - 20; };
}

/// Four spindle runs (no speed channel) whose six thermometers T1…T6 read
/// the parts' temperatures as Σ_p loading[k][p]·pattern_p(t) plus their own
/// `noise` (from the second minute, so each run's zero is exact); the z drift
/// is Σ_p gain[p]·pattern_p(t), each pattern warming and cooling with its own
/// time constant per run.
template <std::size_t Patterns>
Campaign patternCampaign(const std::array<std::array<double, Patterns>, 6>& loading,
                         const std::array<double, Patterns>& gain_um_per_K,
                         const std::function<test::Profile(unsigned seed)>& noiseOf) {
    Campaign c = test::spindleCampaign(6, false);
    for (int r = 0; r < 4; ++r) {
        std::array<double, Patterns> tau{}, end{};
        for (std::size_t p = 0; p < Patterns; ++p) {
            tau[p] = (400.0 + 900.0 * double(p)) * (1 + 0.5 * r);
            end[p] = 2400.0 + 1500.0 * double((p + std::size_t(r)) % 3);
        }
        auto pattern = [=](std::size_t p, double t) {
            return 3.0 * test::warmCool(t, tau[p], end[p]);
        };
        std::map<QString, test::Profile> columns;
        for (std::size_t k = 0; k < 6; ++k) {
            const test::Profile noise = noiseOf(unsigned(100 * r + int(k)));
            columns[QStringLiteral("T%1").arg(k + 1)] = [=](double t) {
                double value = 22 + (t < 60 ? 0.0 : noise(t));
                for (std::size_t p = 0; p < Patterns; ++p) value += loading[k][p] * pattern(p, t);
                return value;
            };
        }
        columns[kZ] = [=](double t) {
            double drift = 0;
            for (std::size_t p = 0; p < Patterns; ++p) drift += gain_um_per_K[p] * pattern(p, t);
            return drift;
        };
        test::addSpindleRun(c, kPatternRun_s, columns);
    }
    return c;
}

TEST(RidgeHeat, spreadsTheGainOverThermometersThatReadOneTemperature) {
    // Six thermometers on one part, each with its own 0.05 K of noise; the
    // drift is 3 µm/K of the part's rise. Least squares trades gains of the
    // six against each other to follow the noise; the penalty the folds
    // choose spreads 3 µm/K over them.
    const Campaign c = patternCampaign<1>({{{1}, {1}, {1}, {1}, {1}, {1}}}, {3},
                                          [](unsigned seed) { return whiteNoise(seed, 0.05); });
    const auto train = test::driftDataset(c, {"SP1", "SP2", "SP3"}, kZ);
    RidgeHeatModel model;
    const FitSummary fit = model.fit(train);
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_GT(fit.metrics.at(QStringLiteral("lambda")), 0) << qPrintable(fit.notes.back());
    double sum = 0;
    for (int k = 1; k <= 6; ++k) {
        const double a = fit.parameters.at(QStringLiteral("T%1.a").arg(k)).value;
        EXPECT_NEAR(a, 0.5, 0.2) << k;
        sum += a;
    }
    EXPECT_NEAR(sum, 3, 0.1);
}

TEST(PcrHeat, takesAsManyComponentsAsTheThermometersHavePatterns) {
    // Six thermometers read two parts (a fast one and a slow one) in
    // different proportions, each with its own slow wander (0.003 K per 15 s,
    // about 0.07 K over a run); the drift follows both parts. Two components
    // carry it; least squares on all six rises also fits the wanders, which
    // differ from run to run.
    const Campaign c = patternCampaign<2>(
        {{{1.0, 0.1}, {0.8, 0.3}, {0.6, 0.5}, {0.4, 0.7}, {0.2, 0.9}, {0.1, 1.0}}}, {1.5, 2.0},
        [](unsigned seed) { return wander(seed, 0.003); });
    const auto train = test::driftDataset(c, {"SP1", "SP2", "SP3"}, kZ);
    const auto heldOut = test::driftDataset(c, {"SP4"}, kZ);
    PrincipalRisesHeatModel model;
    const FitSummary fit = model.fit(train);
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_EQ(fit.metrics.at(QStringLiteral("components")), 2) << qPrintable(fit.notes.back());
    const Score score = scoreModel(model, heldOut);
    ASSERT_TRUE(score.ok()) << qPrintable(score.error);
    EXPECT_LT(score.rms_um, 0.03 * score.uncompensated_rms_um);
    AllRisesHeatModel everyRise;
    ASSERT_TRUE(everyRise.fit(train).success);
    const Score everyRiseScore = scoreModel(everyRise, heldOut);
    ASSERT_TRUE(everyRiseScore.ok()) << qPrintable(everyRiseScore.error);
    EXPECT_LT(score.rms_um, 0.8 * everyRiseScore.rms_um);
}

}  // namespace
}  // namespace driftlab::models
