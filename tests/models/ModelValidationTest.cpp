// A fit's trust from its training runs alone: its cross-validation against no
// compensation, and a prediction interval whose coverage on runs the fit did
// not see is what it claims.

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "core/models/AutoModel.h"
#include "core/models/ModelValidation.h"
#include "core/rig/CampaignSimulator.h"
#include "tests/models/ModelTestSupport.h"
#include "tests/models/ValidationRecord.h"

namespace driftlab::models {
namespace {

std::vector<RunData> dataOf(const Campaign& c, const QStringList& ids) {
    const DatasetResult d = buildDataset(c, ids);
    EXPECT_TRUE(d.ok()) << qPrintable(d.error);
    return d.runs;
}

TEST(ModelValidation, foldsLeaveEachRunOutAndScoreEveryRunsLastThirtyPercent) {
    const Campaign c = test::twoSensorCampaign(3, {});
    const std::vector<RunData> runs =
        dataOf(c, {QStringLiteral("S1"), QStringLiteral("S2"), QStringLiteral("S3")});
    const std::vector<ValidationFold> folds = validationFolds(runs);
    ASSERT_EQ(folds.size(), 4u);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(folds[k].fit_on.size(), 2u);
        ASSERT_EQ(folds[k].held_out.size(), 1u);
        EXPECT_EQ(folds[k].held_out.front().run_id, runs[k].run_id);
    }
    // Passes every 600 s from 600 s to 4 h: 70 % of that span ends at
    // 10 260 s, so cycles 1 … 17 are fitted and 18 … 24 scored, in each run.
    const ValidationFold& inTime = folds.back();
    ASSERT_EQ(inTime.held_out.size(), 3u);
    for (std::size_t r = 0; r < 3; ++r) {
        EXPECT_EQ(inTime.fit_on[r].observations.size(), 17u * 16u);
        EXPECT_EQ(inTime.held_out[r].observations.size(), 7u * 16u);
        EXPECT_GT(inTime.held_out[r].observations.front().time_s, 10260);
    }
    EXPECT_EQ(validationFolds({runs.front()}).size(), 1u);
}

TEST(ModelValidation, theIntervalIsTheConformalQuantileOfTheHeldOutResiduals) {
    // Residuals 1, 2, …, 40 µm: the interval is the ⌈41 · 0.95⌉ = 39th smallest.
    HeldOutPredictions p;
    for (int i = 1; i <= 40; ++i) {
        p.measured_um.push_back(i % 2 ? i : -i);
        p.predicted_um.push_back(0);
        p.position_mm.push_back(0);
    }
    p.part_ends = {20, 40};
    const Validation v = validationOf(p, false, 2);
    EXPECT_DOUBLE_EQ(v.interval.half_width_um, 39);
    EXPECT_DOUBLE_EQ(v.rms_um, v.none_rms_um);
    EXPECT_FALSE(v.worseThanNone());  // none itself does no harm
    EXPECT_EQ(v.readings, 40u);
    // Twenty readings or fewer: the largest.
    p.measured_um.resize(20);
    p.predicted_um.resize(20);
    p.position_mm.resize(20);
    p.part_ends = {20};
    EXPECT_DOUBLE_EQ(validationOf(p, false, 1).interval.half_width_um, 20);
}

TEST(ModelValidation, beyondTheTrainingRunsTheIntervalComesFromTheFoldsThatExtrapolated) {
    // Two parts of 20 readings: residuals ±1 µm where the fold interpolated,
    // ±1 … ±20 µm where its held-out run went beyond the runs it fitted on.
    HeldOutPredictions p;
    for (int i = 1; i <= 20; ++i) {
        p.measured_um.push_back(i % 2 ? 1 : -1);
        p.predicted_um.push_back(0);
        p.position_mm.push_back(0);
    }
    for (int i = 1; i <= 20; ++i) {
        p.measured_um.push_back(i % 2 ? i : -i);
        p.predicted_um.push_back(0);
        p.position_mm.push_back(0);
    }
    p.part_ends = {20, 40};
    p.part_beyond = {false, true};
    const PredictionInterval interval = validationOf(p, false, 2).interval;
    // Pooled: the 39th smallest of twenty 1s and 1 … 20 is 19; beyond: the
    // largest of the extrapolation's twenty (too few for the 95 % rank).
    EXPECT_DOUBLE_EQ(interval.half_width_um, 19);
    ASSERT_TRUE(interval.knownBeyond());
    EXPECT_DOUBLE_EQ(interval.beyond_half_width_um, 20);
    EXPECT_EQ(interval.beyond_readings, 20u);
    EXPECT_DOUBLE_EQ(interval.halfWidthAt(0), 19);
    EXPECT_DOUBLE_EQ(interval.halfWidthAt(0, true), 20);
    // Never narrower beyond than within: the wider of both.
    PredictionInterval narrowBeyond = interval;
    narrowBeyond.beyond_half_width_um = 5;
    EXPECT_DOUBLE_EQ(narrowBeyond.halfWidthAt(0, true), 19);
    // Too few readings of extrapolations: no interval beyond, the pooled one
    // stands and the notes say it is not known to hold there.
    p.part_beyond = {false, false};
    const Validation none = validationOf(p, false, 2);
    EXPECT_FALSE(none.interval.knownBeyond());
    EXPECT_DOUBLE_EQ(none.interval.halfWidthAt(0, true), 19);
    EXPECT_TRUE(validationNotes(none).join(' ').contains("not known to hold"));
}

TEST(ModelValidation, aPositioningIntervalGrowsWithTheResidualsAlongTheScrew) {
    // At 0 mm residuals of ±0.1 µm, at 700 mm of ±1 µm, 20 of each.
    HeldOutPredictions p;
    for (int i = 0; i < 20; ++i)
        for (double x : {0.0, 700.0}) {
            p.measured_um.push_back((x > 0 ? 1.0 : 0.1) * (i % 2 ? 1 : -1));
            p.predicted_um.push_back(0);
            p.position_mm.push_back(x);
        }
    p.part_ends = {p.measured_um.size()};
    const PredictionInterval interval = validationOf(p, true, 1).interval;
    ASSERT_EQ(interval.position_mm.size(), 2u);
    EXPECT_DOUBLE_EQ(interval.halfWidthAt(0), 0.1);
    EXPECT_DOUBLE_EQ(interval.halfWidthAt(700), 1.0);
    EXPECT_DOUBLE_EQ(interval.halfWidthAt(350), 0.55);
    EXPECT_DOUBLE_EQ(interval.halfWidthAt(900), 1.0);  // held beyond the targets
}

TEST(ModelValidation, autoChoosesNoCompensationWhereTheDriftIsPureNoise) {
    // The sensors warm and cool, but the thermal error is white noise of
    // 1 µm: every family fits noise, and none does better than nothing.
    Campaign c = test::twoSensorCampaign(3, {0, 0, 0, 0});
    std::mt19937 rng(11);
    std::normal_distribution<double> noise(0.0, 1.0);
    for (driftlab::Run& run : c.runs)
        for (PositioningMeasurement& m : run.positioning)
            if (m.cycle > 0) m.deviation_um += noise(rng);
    const std::vector<RunData> runs =
        dataOf(c, {QStringLiteral("S1"), QStringLiteral("S2"), QStringLiteral("S3")});
    const ValidatedFit fit = fitValidated(QStringLiteral("auto"), runs);
    ASSERT_TRUE(fit.fit.success) << qPrintable(fit.fit.message);
    EXPECT_EQ(static_cast<const AutoModel&>(*fit.model).chosen(), QStringLiteral("none"));
    EXPECT_TRUE(fit.fit.notes.front().startsWith(QStringLiteral(
        "auto chose no compensation: no model family does better than none by cross-validation")))
        << qPrintable(fit.fit.notes.front());
    EXPECT_FALSE(fit.validation.worseThanNone());
    const Prediction p = fit.model->predict(runs.front());
    ASSERT_TRUE(p.ok());
    for (double e : p.error_um) EXPECT_EQ(e, 0);
    // A single family on the same runs is worse than none, and says so.
    const ValidatedFit mlr = fitValidated(QStringLiteral("mlr"), runs);
    ASSERT_TRUE(mlr.fit.success);
    EXPECT_TRUE(mlr.validation.worseThanNone()) << qPrintable(mlr.validation.describe());
    EXPECT_TRUE(mlr.fit.notes.last().startsWith(
        QStringLiteral("worse than no compensation where it was not fitted")));
}

TEST(ModelValidation, theIntervalCoversWhatItClaimsOnTheRigsHeldOutRuns) {
    // Trained on three moving states, scored on two others; 95 % claimed.
    static const Campaign rig = rig::simulateCampaign(rig::RigSpec{});
    const std::vector<RunData> train =
        dataOf(rig, {QStringLiteral("S1"), QStringLiteral("S2"), QStringLiteral("S3")});
    const std::vector<RunData> test = dataOf(rig, {QStringLiteral("S4"), QStringLiteral("S5")});
    for (const QString& name : {QStringLiteral("heat-transfer"), QStringLiteral("auto")}) {
        const ValidatedFit fit = fitValidated(name, train);
        ASSERT_TRUE(fit.fit.success) << qPrintable(fit.fit.message);
        const Coverage c = coverageOf(*fit.model, fit.validation.interval, test, train);
        ASSERT_TRUE(c.known()) << qPrintable(name);
        EXPECT_NEAR(c.share, 0.95, 0.10) << qPrintable(name);
        EXPECT_FALSE(c.farBelowClaim()) << qPrintable(name);
        test::writeValidationRecord(
            QStringLiteral("coverage"), QStringLiteral("rig-") + name,
            {{QStringLiteral("campaign"), QStringLiteral("simulated rig, five moving states")},
             {QStringLiteral("model"), name},
             {QStringLiteral("train"), QStringLiteral("S1,S2,S3")},
             {QStringLiteral("test"), QStringLiteral("S4,S5")},
             {QStringLiteral("interval_um"), fit.validation.interval.half_width_um},
             {QStringLiteral("readings"), qint64(c.readings)},
             {QStringLiteral("coverage"), c.share}});
    }
}

}  // namespace
}  // namespace driftlab::models
