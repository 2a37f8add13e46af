// Scoring on held-out runs, the cross-state matrix and the model factory.

#include <gtest/gtest.h>
#include <cmath>

#include "core/models/MlrModel.h"
#include "core/models/ModelFactory.h"
#include "core/models/ModelScore.h"
#include "tests/models/ModelTestSupport.h"

namespace driftlab::models {
namespace {

std::vector<RunData> threeStates() {
    // The gains differ from state to state, as the thermal behaviour of an axis
    // does with its feed and stroke: a model fitted on one state is off on another.
    const Campaign c = test::twoSensorCampaign(3, {}, [](int run) { return 1.0 + 0.3 * run; });
    const DatasetResult data =
        buildDataset(c, {QStringLiteral("S1"), QStringLiteral("S2"), QStringLiteral("S3")});
    EXPECT_TRUE(data.ok()) << qPrintable(data.error);
    return data.runs;
}

TEST(ModelScore, rmsPeakAndReductionOfAHandCheckableCase) {
    Eigen::VectorXd measured(4), predicted(4);
    measured << 3, -4, 0, 5;
    predicted << 2, -2, 0, 5;  // residuals 1, -2, 0, 0
    const Score s = scoreResiduals(measured, predicted);
    ASSERT_TRUE(s.ok()) << qPrintable(s.error);
    EXPECT_DOUBLE_EQ(s.rms_um, std::sqrt(5.0 / 4));
    EXPECT_DOUBLE_EQ(s.peak_um, 2);
    EXPECT_DOUBLE_EQ(s.uncompensated_rms_um, std::sqrt(50.0 / 4));
    EXPECT_DOUBLE_EQ(s.reduction, 1 - std::sqrt(5.0 / 50));
    EXPECT_EQ(s.observations, 4u);
}

TEST(ModelScore, mismatchedOrEmptyInputIsAnError) {
    EXPECT_EQ(scoreResiduals(Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(2)).error,
              QStringLiteral("3 measurements but 2 predictions"));
    EXPECT_EQ(scoreResiduals(Eigen::VectorXd(), Eigen::VectorXd()).error,
              QStringLiteral("no observations to score"));
    const Score none = scoreResiduals(Eigen::VectorXd::Zero(2), Eigen::VectorXd::Ones(2));
    EXPECT_TRUE(none.ok());
    EXPECT_TRUE(std::isnan(none.reduction));  // no thermal error to reduce
}

TEST(ModelScore, poolsTheObservationsOfAllTestRuns) {
    const std::vector<RunData> runs = threeStates();
    MlrModel model;
    ASSERT_TRUE(model.fit({runs[0]}).success);
    const Score pooled = scoreModel(model, {runs[1], runs[2]});
    ASSERT_TRUE(pooled.ok()) << qPrintable(pooled.error);
    double squares = 0, measuredSquares = 0, peak = 0;
    for (const RunData* run : {&runs[1], &runs[2]}) {
        const Prediction p = model.predict(*run);
        ASSERT_TRUE(p.ok());
        for (std::size_t i = 0; i < run->observations.size(); ++i) {
            const double r = run->observations[i].error_um - p.error_um[i];
            squares += r * r;
            measuredSquares += run->observations[i].error_um * run->observations[i].error_um;
            peak = std::max(peak, std::abs(r));
        }
    }
    const double n = double(runs[1].observations.size() + runs[2].observations.size());
    EXPECT_EQ(pooled.observations, std::size_t(n));
    EXPECT_NEAR(pooled.rms_um, std::sqrt(squares / n), 1e-12);
    EXPECT_NEAR(pooled.peak_um, peak, 1e-12);
    EXPECT_NEAR(pooled.reduction, 1 - std::sqrt(squares / measuredSquares), 1e-12);
}

TEST(ModelScore, unfittedModelScoresAsAnError) {
    MlrModel model;
    EXPECT_EQ(scoreModel(model, threeStates()).error, QStringLiteral("model 'mlr' is not fitted"));
}

TEST(CrossStateMatrix, fitsOnEachRunAndScoresOnEveryRun) {
    const std::vector<RunData> runs = threeStates();
    const CrossStateMatrix m = crossStateMatrix(QStringLiteral("mlr"), runs);
    EXPECT_TRUE(m.errors.isEmpty()) << qPrintable(m.errors.join(u'\n'));
    EXPECT_EQ(m.runs,
              QStringList({QStringLiteral("S1"), QStringLiteral("S2"), QStringLiteral("S3")}));
    ASSERT_EQ(m.rms_um.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        ASSERT_EQ(m.rms_um[i].size(), 3u);
        MlrModel alone;
        const FitSummary fit = alone.fit({runs[i]});
        ASSERT_TRUE(fit.success) << qPrintable(fit.message);
        // The diagonal is the training RMS; the other states are predicted worse.
        EXPECT_NEAR(m.rms_um[i][i], fit.rms_um, 1e-12);
        for (std::size_t j = 0; j < 3; ++j)
            if (j != i) {
                EXPECT_GT(m.rms_um[i][j], m.rms_um[i][i] + 0.1) << i << "," << j;
            }
    }
}

TEST(CrossStateMatrix, reportsAFailedFitAndCanBeCancelled) {
    const CrossStateMatrix unknown = crossStateMatrix(QStringLiteral("neural"), threeStates());
    ASSERT_EQ(unknown.errors.size(), 1);
    EXPECT_TRUE(unknown.errors.front().startsWith(QStringLiteral("unknown model 'neural'")));
    EXPECT_TRUE(std::isnan(unknown.rms_um[0][0]));

    // These runs log no motor torque: every sensorless fit fails, each says why.
    const CrossStateMatrix sensorless =
        crossStateMatrix(QStringLiteral("sensorless"), threeStates());
    ASSERT_EQ(sensorless.errors.size(), 3);
    EXPECT_EQ(sensorless.errors.front(),
              QStringLiteral("fit on run 'S1': model 'sensorless' needs the motor torque: run 'S1' "
                             "has no samples in column 'torque_Nm'"));

    // Asked before each fit and, through the model's cancel check, at the end
    // of it: the third question is the one before the second fit.
    int calls = 0;
    const CrossStateMatrix cancelled =
        crossStateMatrix(QStringLiteral("mlr"), threeStates(), [&](double) { return ++calls < 3; });
    EXPECT_TRUE(cancelled.cancelled);
    EXPECT_EQ(calls, 3);
    EXPECT_FALSE(std::isnan(cancelled.rms_um[0][0]));
    EXPECT_TRUE(std::isnan(cancelled.rms_um[1][1]));
}

TEST(ModelFactory, makesEveryNamedModel) {
    EXPECT_EQ(modelNames(),
              QStringList({QStringLiteral("mlr"), QStringLiteral("poly-position"),
                           QStringLiteral("exponential"), QStringLiteral("heat-transfer"),
                           QStringLiteral("sensorless"), QStringLiteral("arx"),
                           QStringLiteral("arx-all"), QStringLiteral("lsall-heat"),
                           QStringLiteral("ridge-heat"), QStringLiteral("pcr-heat")}));
    // A single fit may also ask for "auto" and "none" (no compensation), which
    // are no families of their own and so stay out of the comparisons.
    EXPECT_EQ(fitModelNames(), modelNames() << QStringLiteral("auto") << QStringLiteral("none"));
    for (const QString& name : fitModelNames()) {
        const auto model = makeModel(name);
        ASSERT_TRUE(model) << qPrintable(name);
        EXPECT_EQ(model->name(), name);
        EXPECT_FALSE(model->describe().isEmpty());
    }
    EXPECT_EQ(makeModel(QStringLiteral("crystal-ball")), nullptr);
}

TEST(ThermalErrorModel, predictionOfAnotherTargetIsAnError) {
    const std::vector<RunData> runs = threeStates();
    MlrModel model;
    ASSERT_TRUE(model.fit({runs[0]}).success);
    RunData drift = runs[1];
    drift.target_channel = QStringLiteral("D_x");
    EXPECT_EQ(model.predict(drift).error,
              QStringLiteral("model 'mlr' was fitted to the positioning error; run 'S2' asks for "
                             "channel 'D_x'"));
}

}  // namespace
}  // namespace driftlab::models
