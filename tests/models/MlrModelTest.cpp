// Multiple linear regression with sensor selection: exact recovery of a
// two-sensor model among distractors, the best single sensor, predictions at
// any point, drift targets and channels that cannot be used; the subset
// search's cross-validation from normal equations against a QR per fold.

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/models/CrossValidation.h"
#include "core/models/MlrModel.h"
#include "core/models/RunDataAccess.h"
#include "tests/models/ModelTestSupport.h"

namespace driftlab::models {
namespace {

using test::TwoSensorGains;

std::vector<RunData> dataset(const Campaign& c, const QStringList& runs) {
    const DatasetResult data = buildDataset(c, runs);
    EXPECT_TRUE(data.ok()) << qPrintable(data.error);
    return data.runs;
}

void expectRelative(const FitSummary& fit, const QString& name, double expected) {
    ASSERT_TRUE(fit.parameters.count(name)) << qPrintable(name);
    EXPECT_NEAR(fit.parameters.at(name).value, expected, 1e-9 * std::abs(expected))
        << qPrintable(name);
}

void expectTwoSensorGains(const FitSummary& fit, const TwoSensorGains& g) {
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_EQ(fit.inputs, QStringList({QStringLiteral("T_nut"), QStringLiteral("T_bearing")}));
    EXPECT_EQ(fit.parameters.size(), 4u);
    expectRelative(fit, QStringLiteral("T_nut.a"), g.a1);
    expectRelative(fit, QStringLiteral("T_nut.b"), g.b1);
    expectRelative(fit, QStringLiteral("T_bearing.a"), g.a2);
    expectRelative(fit, QStringLiteral("T_bearing.b"), g.b2);
    EXPECT_EQ(fit.parameters.at(QStringLiteral("T_nut.b")).unit, QStringLiteral("µm/(K·mm)"));
    EXPECT_LT(fit.rms_um, 1e-9);
}

TEST(MlrModel, recoversTwoSensorsAmongFiveCandidatesExactly) {
    const TwoSensorGains gains;
    const Campaign c = test::twoSensorCampaign(2, gains);
    MlrModel model;
    const FitSummary fit = model.fit(dataset(c, {QStringLiteral("S1"), QStringLiteral("S2")}));
    expectTwoSensorGains(fit, gains);
    EXPECT_EQ(fit.observations, 2u * 24u * 16u);
    // The best subset of each size was tried; three sensors add nothing.
    ASSERT_EQ(model.bestSubsets().size(), 3u);
    EXPECT_EQ(model.bestSubsets()[1].sensors, fit.inputs);
    EXPECT_LT(model.bestSubsets()[1].cv_rms_um, 1e-9);
}

TEST(MlrModel, singleTrainingRunIsCrossValidatedOverTimeBlocks) {
    const TwoSensorGains gains;
    MlrModel model;
    expectTwoSensorGains(
        model.fit(dataset(test::twoSensorCampaign(1, gains), {QStringLiteral("S1")})), gains);
}

TEST(MlrModel, reportsTheBestSingleSensorAndItsRSquared) {
    const Campaign c = test::twoSensorCampaign(2, {});
    MlrModel model;
    const FitSummary fit = model.fit(dataset(c, {QStringLiteral("S1"), QStringLiteral("S2")}));
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    const QString single = model.bestSubsets().front().sensors.front();
    EXPECT_TRUE(single == QStringLiteral("T_nut") || single == QStringLiteral("T_bearing"));
    const double r2 = fit.metrics.at(QStringLiteral("best_single_r2"));
    EXPECT_GT(r2, 0.5);
    EXPECT_LT(r2, 1.0);
    EXPECT_GT(fit.metrics.at(QStringLiteral("best_single_cv_rms_um")),
              fit.metrics.at(QStringLiteral("cv_rms_um")));
    EXPECT_TRUE(fit.notes.contains(
        QStringLiteral("best single sensor: %1 (R² = %2, cross-validated RMS %3 µm)")
            .arg(single)
            .arg(r2, 0, 'f', 4)
            .arg(fit.metrics.at(QStringLiteral("best_single_cv_rms_um")), 0, 'g', 3)));
}

TEST(MlrModel, predictsAtAnyTimeAndPositionFromTheRunsTemperatures) {
    const TwoSensorGains g;
    const Campaign c = test::twoSensorCampaign(2, g);
    const std::vector<RunData> runs = dataset(c, {QStringLiteral("S1"), QStringLiteral("S2")});
    MlrModel model;
    ASSERT_TRUE(model.fit({runs[0]}).success);
    const std::vector<PredictionPoint> at{{1234.5, 333.0}, {7000, 0}};
    const Prediction p = model.predict(runs[1], at);
    ASSERT_TRUE(p.ok()) << qPrintable(p.error);
    const Eigen::MatrixXd rises =
        risesAt(runs[1], {QStringLiteral("T_nut"), QStringLiteral("T_bearing")}, at);
    for (std::size_t i = 0; i < at.size(); ++i) {
        const double dx = at[i].position_mm - test::kFixedEndMm;
        const Eigen::Index r = Eigen::Index(i);
        EXPECT_NEAR(p.error_um[i],
                    rises(r, 0) * (g.a1 + g.b1 * dx) + rises(r, 1) * (g.a2 + g.b2 * dx), 1e-9);
    }
}

TEST(MlrModel, fitsAroundAHoleItCannotBridgeOnTheReadingsOutsideIt) {
    Campaign c = test::twoSensorCampaign(2, {});
    std::vector<double>& bed = c.runs[1].samples.values[3];  // T_bed of S2, a random walk
    for (std::size_t i = 600; i < 700; ++i) bed[i] = std::nan("");
    const std::vector<RunData> runs = dataset(c, {QStringLiteral("S1"), QStringLiteral("S2")});
    ASSERT_EQ(runs[1].gaps.size(), 1u);
    const DataGap& gap = runs[1].gaps.front();
    EXPECT_EQ(gap.channel, QStringLiteral("T_bed"));
    EXPECT_FALSE(gap.bridged) << gap.bridge_error << " K against " << gap.tolerance;
    // The passes at 6000 and 6600 s fall in the hole (5990 … 7000 s).
    EXPECT_EQ(gap.observations_left_out, 2u * 16u);
    MlrModel model;
    const FitSummary fit = model.fit(runs);
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_EQ(fit.observations, 2u * 24u * 16u - 2u * 16u);
    EXPECT_EQ(fit.inputs, QStringList({QStringLiteral("T_nut"), QStringLiteral("T_bearing")}));
}

TEST(MlrModel, ambientReferenceRegressesOnRisesAboveAmbient) {
    Campaign c = test::feedAxisCampaign({{QStringLiteral("T_nut"), ChannelRole::Nut},
                                         {QStringLiteral("T_ambient"), ChannelRole::Ambient}});
    auto nut = [](double t) { return 5 * test::warmCool(t, 900, 1e4); };
    auto ambient = [](double t) { return std::sin(std::max(0.0, t - 60) / 2000); };
    driftlab::Run run = test::sampledRun(
        c, QStringLiteral("S1"), 4 * 3600, 10,
        {{QStringLiteral("T_nut"), [=](double t) { return 20 + nut(t); }},
         {QStringLiteral("T_ambient"), [=](double t) { return 20 + ambient(t); }}});
    test::addPositioning(run, 600, 4 * 3600, [=](double t, double x) {
        return (nut(t) - ambient(t)) * (0.5 + 0.01 * (x - test::kFixedEndMm));
    });
    c.runs.push_back(run);
    MlrOptions options;
    options.ambient_reference = true;
    MlrModel model(options);
    const FitSummary fit = model.fit(dataset(c, {QStringLiteral("S1")}));
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_EQ(fit.inputs, QStringList({QStringLiteral("T_nut"), QStringLiteral("T_ambient")}));
    expectRelative(fit, QStringLiteral("T_nut.a"), 0.5);
    expectRelative(fit, QStringLiteral("T_nut.b"), 0.01);
}

TEST(MlrModel, driftTargetHasAnOffsetAndNoPositionTerm) {
    Campaign c = test::feedAxisCampaign({{QStringLiteral("T_spindle"), ChannelRole::Spindle},
                                         {QStringLiteral("T_bed"), ChannelRole::Structure}});
    c.channels.push_back(
        {QStringLiteral("D_z"), Quantity::Displacement, ChannelRole::DriftZ, {}, {}, {}});
    c.sample_columns.push_back(QStringLiteral("D_z"));
    auto spindle = [](double t) { return 4 * test::warmCool(t, 1200, 5400); };
    driftlab::Run run = test::sampledRun(
        c, QStringLiteral("SP1"), 7200, 15,
        {{QStringLiteral("T_spindle"), [=](double t) { return 22 + spindle(t); }},
         {QStringLiteral("T_bed"), test::randomWalk(7, 0.02, 15, 7200)},
         {QStringLiteral("D_z"), [=](double t) { return 0.7 - 2.5 * spindle(t); }}});
    run.kind = RunKind::Spindle;
    c.runs.push_back(run);
    DatasetOptions options;
    options.target_channel = QStringLiteral("D_z");
    const DatasetResult data = buildDataset(c, {QStringLiteral("SP1")}, options);
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    MlrModel model;
    const FitSummary fit = model.fit(data.runs);
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_EQ(fit.inputs, QStringList({QStringLiteral("T_spindle")}));
    expectRelative(fit, QStringLiteral("T_spindle.a"), -2.5);
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("c")).value, 0, 1e-9);
    EXPECT_FALSE(fit.parameters.count(QStringLiteral("T_spindle.b")));
}

}  // namespace
}  // namespace driftlab::models

namespace driftlab::models {
namespace {

TEST(CrossValidation, normalEquationsPerFoldScoreEverySubsetAsTheFoldsOwnQrDoes) {
    // The best-subset search scores subsets from each fold's summed normal
    // equations; it must give what a QR of the fold's rows gives, and fall back
    // to that QR where a subset is (nearly) collinear.
    std::mt19937 rng(7);
    std::normal_distribution<double> normal;
    const Eigen::Index n = 600;
    Eigen::MatrixXd X(n, 6);
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < 4; ++j) X(i, j) = 3 * normal(rng) + double(j);
    X.col(4) = X.col(1) * 2 - X.col(2);  // exactly collinear with columns 1 and 2
    X.col(5).setOnes();                  // an offset
    const Eigen::VectorXd y = X.leftCols(2) * Eigen::Vector2d(1.5, -0.7) +
                              Eigen::VectorXd::NullaryExpr(n, [&] { return normal(rng); });
    std::vector<int> folds(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < folds.size(); ++i) folds[i] = int(3 * i / folds.size());
    const FoldNormalEquations normal3(X, y, folds);
    for (const std::vector<Eigen::Index>& columns :
         std::vector<std::vector<Eigen::Index>>{{0, 5}, {0, 1, 5}, {1, 2, 3, 5}, {3}}) {
        const double qr = crossValidatedRms(X(Eigen::all, columns), y, folds);
        EXPECT_NEAR(normal3.crossValidatedRms(columns), qr, 1e-9 * qr);
        EXPECT_GT(qr, 0.9);  // the noise's RMS is 1
    }
    const std::vector<Eigen::Index> collinear{1, 2, 4, 5};
    EXPECT_EQ(normal3.crossValidatedRms(collinear),
              crossValidatedRms(X(Eigen::all, collinear), y, folds));
    EXPECT_EQ(normal3.crossValidatedRms(collinear), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace driftlab::models
