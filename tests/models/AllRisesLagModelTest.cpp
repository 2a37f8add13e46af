// `arx-all`: every temperature rise plus a lagged rise and the drive's lagged
// heat, against closed forms — a drift that is a static sum of five sensors
// plus one sensor through a lag, a drift with no lag at all, a drift with a
// rotor heated by its own losses that no thermometer sees, and a screw's
// positioning error (the two-sensor model with three distractors).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "core/models/AllRisesLagModel.h"
#include "core/models/ModelScore.h"
#include "tests/models/ModelTestSupport.h"
#include "tests/models/SpindleTestCampaigns.h"
#include "tests/support/LeastSquaresBaselines.h"

namespace driftlab::models {
namespace {

constexpr double kTrailingLag_s = 1800;
constexpr std::array<double, 5> kGain_um_per_K{-1.0, 0.6, -0.4, 1.2, -0.8};
constexpr double kLagGain_um_per_K = -2.0;  ///< of T1's rise through the lag

/// Four spindle runs, five thermometers T1…T5 each heating with its own
/// time constant, amplitude and end of heating in each run; the z drift is Σ a_k·ΔT_k plus,
/// with `lagged`, −2 µm/K times T1's rise through a lag of 1800 s (the part
/// that trails every sensor, as a spindle shaft behind its bearings). The
/// probe reads `firstMinuteShift_um[r]` off in run r's first minute, which
/// the drift's zero is taken from.
Campaign fiveSensorCampaign(bool lagged, std::array<double, 4> firstMinuteShift_um = {}) {
    Campaign c = test::spindleCampaign(5, false);
    for (int r = 0; r < 4; ++r) {
        // Each sensor warms with its own time constant and stops warming at
        // its own time (the cooling of T1 ends the runs, so T1 rises
        // throughout and its lag has the closed form below).
        std::array<double, 5> tau_s{}, rise_K{}, end_s{};
        for (std::size_t k = 0; k < 5; ++k) {
            tau_s[k] = 300.0 * double(k + 1) * (1 + 0.6 * r);
            rise_K[k] = 2.0 + double((k + 2 * std::size_t(r)) % 5);
            end_s[k] = k == 0 ? 1e9 : 1500.0 + 900.0 * double((k + std::size_t(r)) % 5);
        }
        std::map<QString, test::Profile> columns;
        for (std::size_t k = 0; k < 5; ++k)
            columns[QStringLiteral("T%1").arg(k + 1)] = [=](double t) {
                return 22 + rise_K[k] * test::warmCool(t, tau_s[k], end_s[k]);
            };
        columns[QStringLiteral("D_z")] = [=](double t) {
            double drift = 0.3 + (t < 60 ? firstMinuteShift_um[std::size_t(r)] : 0.0);
            for (std::size_t k = 0; k < 5; ++k)
                drift += kGain_um_per_K[k] * rise_K[k] * test::warmCool(t, tau_s[k], end_s[k]);
            if (lagged)
                drift += kLagGain_um_per_K * rise_K[0] *
                         test::lagOfRise(t - 60, tau_s[0], kTrailingLag_s);
            return drift;
        };
        test::addSpindleRun(c, 7200, columns);
    }
    return c;
}

/// `arx-all` fitted on the z drift of SP1–SP3, with SP4 held out.
struct FittedOnThreeRuns {
    explicit FittedOnThreeRuns(const Campaign& c)
        : train(test::driftDataset(c, {"SP1", "SP2", "SP3"}, QStringLiteral("D_z"))),
          held_out(test::driftDataset(c, {"SP4"}, QStringLiteral("D_z"))),
          fit(model.fit(train)) {}
    std::vector<RunData> train, held_out;
    AllRisesLagModel model;
    FitSummary fit;
};

/// The held-out run followed to a few per cent, where least squares on every
/// rise alone (`why`) leaves five times as much.
void expectHeldOutFollowedWhereEveryRiseIsNot(const FittedOnThreeRuns& f, const char* why) {
    const Score score = scoreModel(f.model, f.held_out);
    ASSERT_TRUE(score.ok()) << qPrintable(score.error);
    const test::LeastSquaresBaselines baselines = test::leastSquaresBaselines(f.train, f.held_out);
    EXPECT_LT(score.rms_um, 0.03 * score.uncompensated_rms_um);  // τ on a ×1.5 grid
    EXPECT_LT(score.rms_um, 0.2 * baselines.all_rises.rms_um) << why;
}

TEST(AllRisesLag, recoversEveryGainAndTheLagOfAClosedFormAndPredictsARunHeatedDifferently) {
    const FittedOnThreeRuns f(fiveSensorCampaign(true));
    const FitSummary& fit = f.fit;
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_EQ(fit.inputs.size(), 5);
    ASSERT_TRUE(fit.notes.back().contains(QStringLiteral("T1 through a lag")))
        << qPrintable(fit.notes.back());
    // τ to within one step of the searched grid (×1.5).
    const double tau = fit.parameters.at(QStringLiteral("T1.tau")).value;
    EXPECT_LT(std::abs(std::log(tau / kTrailingLag_s)), std::log(1.5)) << tau;
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("T1.a_lag")).value, kLagGain_um_per_K, 0.3);
    for (int k = 2; k <= 5; ++k)
        EXPECT_NEAR(fit.parameters.at(QStringLiteral("T%1.a").arg(k)).value,
                    kGain_um_per_K[std::size_t(k - 1)], 0.1)
            << k;

    // The fourth run heats each sensor 2.8× slower than the first: least
    // squares on the five rises alone shows the lag as hysteresis.
    expectHeldOutFollowedWhereEveryRiseIsNot(
        f, "every rise without the lag cannot follow the part that trails them");
}

TEST(AllRisesLag, eachTrainingRunsZeroIsFittedApartAndAnOffsetOnlyAllRunsShareIsPredicted) {
    // SP1's first minute reads 0.3 µm high and SP2's 0.2 µm low, as that
    // minute's noise moves a run's zero: each run's zero takes its shift
    // (beside what the clean runs' zeros hold: the lag's ×1.5 grid step and
    // the rises in the first minute leave a tenth of a µm), the gains do not
    // bend to follow it, and a prediction takes no offset.
    const QString z = QStringLiteral("D_z");
    AllRisesLagModel model;
    const FitSummary clean =
        model.fit(test::driftDataset(fiveSensorCampaign(true), {"SP1", "SP2", "SP3"}, z));
    const FitSummary fit = model.fit(
        test::driftDataset(fiveSensorCampaign(true, {0.3, -0.2, 0, 0}), {"SP1", "SP2", "SP3"}, z));
    ASSERT_TRUE(clean.success && fit.success) << qPrintable(fit.message);
    auto value = [](const FitSummary& f, const char* key) {
        return f.parameters.at(QLatin1String(key)).value;
    };
    EXPECT_NEAR(value(fit, "zero.SP1") - value(clean, "zero.SP1"), -0.3, 0.03);
    EXPECT_NEAR(value(fit, "zero.SP2") - value(clean, "zero.SP2"), 0.2, 0.03);
    EXPECT_NEAR(value(fit, "zero.SP3") - value(clean, "zero.SP3"), 0, 0.03);
    EXPECT_NEAR(value(fit, "T1.a_lag"), value(clean, "T1.a_lag"), 0.05);
    EXPECT_FALSE(fit.parameters.count(QStringLiteral("c")));
    EXPECT_EQ(fit.notes.filter(QStringLiteral("a prediction takes none")).size(), 1)
        << qPrintable(fit.notes.join(QStringLiteral(" | ")));

    // Every run's first minute 0.3 µm high (a probe that settles after its
    // first minute): the held-out run's drift sits 0.3 µm low too, and the
    // prediction takes the runs' mean zero.
    const Campaign shared = fiveSensorCampaign(true, {0.3, 0.3, 0.3, 0.3});
    const FitSummary common = model.fit(test::driftDataset(shared, {"SP1", "SP2", "SP3"}, z));
    ASSERT_TRUE(common.success) << qPrintable(common.message);
    ASSERT_TRUE(common.parameters.count(QStringLiteral("c")))
        << qPrintable(common.notes.join(QStringLiteral(" | ")));
    const double cleanMean =
        (value(clean, "zero.SP1") + value(clean, "zero.SP2") + value(clean, "zero.SP3")) / 3;
    // (The lag refitted on the shifted runs leaves some of it to the gains.)
    EXPECT_NEAR(value(common, "c") - cleanMean, -0.3, 0.1);
    const Score score = scoreModel(model, test::driftDataset(shared, {"SP4"}, z));
    ASSERT_TRUE(score.ok()) << qPrintable(score.error);
    EXPECT_LT(score.rms_um, 0.03 * score.uncompensated_rms_um);
}

TEST(AllRisesLag, takesNoLagWhereTheDriftHasNone) {
    const FittedOnThreeRuns f(fiveSensorCampaign(false));
    const FitSummary& fit = f.fit;
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_TRUE(
        fit.notes.back().startsWith(QStringLiteral("every rise (5 channels); no lag lowered")))
        << qPrintable(fit.notes.back());
    EXPECT_FALSE(std::any_of(fit.parameters.begin(), fit.parameters.end(), [](const auto& kv) {
        return kv.first.endsWith(QStringLiteral(".tau"));
    }));
    const Score score = scoreModel(f.model, f.held_out);
    ASSERT_TRUE(score.ok()) << qPrintable(score.error);
    EXPECT_LT(score.rms_um, 1e-3 * score.uncompensated_rms_um);
}

TEST(AllRisesLag, givesTheHeatOfAnUnsensedRotorThroughTheLaggedSpeedSquared) {
    const FittedOnThreeRuns f(test::rotorCampaign());
    const FitSummary& fit = f.fit;
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    ASSERT_TRUE(fit.notes.back().contains(QStringLiteral("the spindle's speed² through a lag")))
        << qPrintable(fit.notes.back());
    const double tau = fit.parameters.at(QStringLiteral("speed².tau")).value;
    EXPECT_LT(std::abs(std::log(tau / test::kRotorLag_s)), std::log(1.5)) << tau;
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("speed².a_lag")).value,
                test::kRotorGain_um_per_krpm2, 0.01);

    // The held-out run goes to 9000 rpm, beyond every training run: the
    // rotor's n² heat there is what the bearings' n-driven rises miss.
    expectHeldOutFollowedWhereEveryRiseIsNot(
        f, "the rises of thermometers the rotor's heat does not reach cannot give it");
}

TEST(AllRisesLag, saysWhyItTakesNoHeatInputWithoutASpeedChannel) {
    AllRisesLagModel model;
    const FitSummary fit = model.fit(
        test::driftDataset(fiveSensorCampaign(false), {"SP1", "SP2"}, QStringLiteral("D_z")));
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_TRUE(fit.notes.contains(QStringLiteral(
        "no lagged heat input: model 'arx-all' needs the spindle speed; this campaign has no "
        "speed channel")))
        << qPrintable(fit.notes.join(QStringLiteral(" | ")));
}

TEST(AllRisesLag, takesNoLaggedHeatFromOneTrainingRun) {
    // The time blocks of one run share its speed programme: they cannot test
    // a heat law on motion the fit has not seen (the cross-state matrix fits
    // on one run).
    AllRisesLagModel model;
    const FitSummary fit =
        model.fit(test::driftDataset(test::rotorCampaign(), {"SP2"}, QStringLiteral("D_z")));
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_TRUE(fit.notes.contains(QStringLiteral(
        "no lagged heat input: one training run, whose time blocks share one speed programme")))
        << qPrintable(fit.notes.join(QStringLiteral(" | ")));
    EXPECT_FALSE(fit.parameters.count(QStringLiteral("speed².tau")) ||
                 fit.parameters.count(QStringLiteral("speed.tau")));
}

TEST(AllRisesLag, fitsAScrewsPositioningErrorWithAGainAlongTheAxis) {
    // E = ΔT_nut·(a1 + b1·dx) + ΔT_bearing·(a2 + b2·dx); T_air, T_bed and
    // T_motor are random walks that carry none of it.
    const test::TwoSensorGains gains;
    const Campaign c = test::twoSensorCampaign(3, gains);
    const DatasetResult train = buildDataset(c, {QStringLiteral("S1"), QStringLiteral("S2")});
    const DatasetResult heldOut = buildDataset(c, {QStringLiteral("S3")});
    ASSERT_TRUE(train.ok() && heldOut.ok());
    AllRisesLagModel model;
    const FitSummary fit = model.fit(train.runs);
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("T_nut.a")).value, gains.a1, 0.02);
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("T_nut.b")).value, gains.b1, 2e-4);
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("T_bearing.a")).value, gains.a2, 0.02);
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("T_bed.a")).value, 0, 0.02);
    // The screw's speed is no input: a lag of it with a gain along the axis,
    // fitted on one moving state, missed others by up to 256 µm on the rig.
    EXPECT_FALSE(std::any_of(fit.parameters.begin(), fit.parameters.end(), [](const auto& kv) {
        return kv.first.startsWith(QStringLiteral("speed"));
    }));
    const Score score = scoreModel(model, heldOut.runs);
    ASSERT_TRUE(score.ok()) << qPrintable(score.error);
    EXPECT_LT(score.rms_um, 0.01 * score.uncompensated_rms_um);
}

}  // namespace
}  // namespace driftlab::models
