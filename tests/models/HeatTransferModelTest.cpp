// heat-transfer on campaigns from the simulated rig: it must find the rig's
// own heat coefficients, predict moving states it was not fitted on, and beat
// the temperature regressions across states as the published studies found.
#include <gtest/gtest.h>

#include <cmath>

#include "core/models/HeatTransferModel.h"
#include "core/models/ModelFactory.h"
#include "core/models/ModelScore.h"
#include "core/rig/CampaignSimulator.h"

using namespace driftlab;
using namespace driftlab::models;

namespace {

/// The default rig campaign (five moving states, no hidden effect), simulated once.
const Campaign& rigCampaign() {
    static const Campaign campaign = rig::simulateCampaign(rig::RigSpec{});
    return campaign;
}

std::vector<RunData> runs(const Campaign& campaign, const QStringList& ids) {
    DatasetResult d = buildDataset(campaign, ids);
    EXPECT_TRUE(d.ok()) << qPrintable(d.error);
    return d.runs;
}

}  // namespace

TEST(HeatTransferModel, recoversTheRigsHeatCoefficientsAndPredictsEveryOtherState) {
    const rig::RigSpec truth;
    HeatTransferModel model;
    const FitSummary fit = model.fit(runs(rigCampaign(), {QStringLiteral("S1")}));
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    // Identified from default initial guesses (c_nut 0.05, c_b 0.05, h 8).
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("c_nut")).value, truth.screw.c_nut_W_per_rad_s,
                0.1 * truth.screw.c_nut_W_per_rad_s);
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("c_b")).value, truth.screw.c_bearing_W_per_rad_s,
                0.1 * truth.screw.c_bearing_W_per_rad_s);
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("h")).value, truth.screw.h_W_m2K,
                0.1 * truth.screw.h_W_m2K);
    for (const auto& [name, p] : fit.parameters) {
        EXPECT_TRUE(std::isfinite(p.sigma)) << qPrintable(name);
        EXPECT_GT(p.sigma, 0) << qPrintable(name);
    }
    EXPECT_TRUE(fit.notes.isEmpty()) << qPrintable(fit.notes.join('\n'));
    EXPECT_GT(fit.iterations, 1);

    for (const char* id : {"S2", "S3", "S4", "S5"}) {
        const Score s = scoreModel(model, runs(rigCampaign(), {QString::fromLatin1(id)}));
        ASSERT_TRUE(s.ok()) << qPrintable(s.error);
        EXPECT_GE(s.reduction, 0.9)
            << id << ": RMS " << s.rms_um << " of " << s.uncompensated_rms_um << " µm";
        // What is left is the interferometer noise (0.3 µm per reading, twice
        // through the cycle-0 difference).
        EXPECT_LT(s.rms_um, 0.8) << id;
    }
}

TEST(HeatTransferModel, regressionFittedOnOneStateFailsOnOthersWherePhysicsDoesNot) {
    const auto s1 = runs(rigCampaign(), {QStringLiteral("S1")});
    auto mlr = makeModel(QStringLiteral("mlr"));
    ASSERT_TRUE(mlr->fit(s1).success);
    HeatTransferModel physics;
    ASSERT_TRUE(physics.fit(s1).success);
    for (const char* id : {"S4", "S5"}) {
        const auto test = runs(rigCampaign(), {QString::fromLatin1(id)});
        const double regression = scoreModel(*mlr, test).rms_um;
        const double simulation = scoreModel(physics, test).rms_um;
        EXPECT_GT(regression, 3 * simulation)
            << id << ": mlr(S1) " << regression << " µm, heat-transfer(S1) " << simulation << " µm";
    }
}

TEST(HeatTransferModel, saysWhenTheDataCannotSeparateTwoParameters) {
    // A run whose axis never moves: nut and bearing heat have no effect, so
    // c_nut and c_b are not determined by anything.
    Campaign still = rigCampaign();
    driftlab::Run& run = still.runs.front();
    const double end = run.motion.back().end_s;
    run.motion = {{0, end, 210, 210, 0}};
    HeatTransferModel model;
    const FitSummary fit = model.fit(runs(still, {run.id}));
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    ASSERT_FALSE(fit.notes.isEmpty());
    EXPECT_TRUE(fit.notes.join(' ').contains(QStringLiteral("not identifiable")));
    EXPECT_TRUE(fit.notes.join(' ').contains(QStringLiteral("c_nut")));
    EXPECT_TRUE(std::isnan(fit.parameters.at(QStringLiteral("c_nut")).sigma));
}

TEST(HeatTransferModel, needsAnAmbientChannelAndTheScrew) {
    Campaign noAmbient = rigCampaign();
    for (auto& c : noAmbient.channels)
        if (c.role == ChannelRole::Ambient) c.role = ChannelRole::Other;
    HeatTransferModel model;
    FitSummary fit = model.fit(runs(noAmbient, {QStringLiteral("S1")}));
    EXPECT_FALSE(fit.success);
    EXPECT_TRUE(fit.message.contains(QStringLiteral("role 'ambient'"))) << qPrintable(fit.message);

    // A long hole in the ambient log: the screw simulates on through it and
    // the passes inside a hole it cannot bridge are not fitted.
    Campaign gap = rigCampaign();
    driftlab::Run& run = gap.runs.front();
    auto& ambient =
        run.samples.values[std::size_t(run.samples.columnIndex(QStringLiteral("T_ambient")))];
    for (std::size_t i = 300; i < 400; ++i) ambient[i] = std::nan("");
    const std::vector<RunData> withHole = runs(gap, {QStringLiteral("S1")});
    ASSERT_EQ(withHole.front().gaps.size(), 1u);
    EXPECT_EQ(withHole.front().gaps.front().channel, QStringLiteral("T_ambient"));
    fit = model.fit(withHole);
    EXPECT_TRUE(fit.success) << qPrintable(fit.message);
}

TEST(HeatTransferModel, identificationGridIsConvergedAgainstTheRigsGrid) {
    // The fit runs on 100 cells and 2 s steps; the rig on 200 cells and 1 s.
    // With the rig's own coefficients, the coarse simulation must reproduce
    // the fine one far below the interferometer noise.
    const auto s3 = runs(rigCampaign(), {QStringLiteral("S3")});
    const ScrewRunInputs coarse = prepareScrewRun(s3[0], 2, QStringLiteral("test"));
    const ScrewRunInputs fine = prepareScrewRun(s3[0], 0.5, QStringLiteral("test"));
    const rig::RigSpec truth;
    const auto points = s3[0].observationPoints();
    const auto a = simulateScrewRun(coarse, screwParameters(s3[0], truth.screw, 100), points);
    const auto b = simulateScrewRun(fine, screwParameters(s3[0], truth.screw, 400), points);
    double worst = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
        worst = std::max(worst, std::abs(a.error_um[i] - b.error_um[i]));
    EXPECT_LT(worst, 0.1) << "largest difference 100 cells/2 s vs 400 cells/0.5 s, µm";
}

TEST(HeatTransferModel, aRunPreparedWithItsNutPathSimulatesAsOneCutStepByStep) {
    // The identification prepares each run with the nut's path cut once for
    // its grid; the simulation must be the one that cuts it at every step,
    // and a simulation on another grid must not use the path.
    const auto s3 = runs(rigCampaign(), {QStringLiteral("S3")});
    const ScrewRunInputs cutOnce =
        prepareScrewRun(s3[0], 2, QStringLiteral("test"), RoomInput::Channel, 100);
    const ScrewRunInputs stepByStep = prepareScrewRun(s3[0], 2, QStringLiteral("test"));
    ASSERT_TRUE(cutOnce.nut_path);
    ASSERT_FALSE(stepByStep.nut_path);
    const rig::RigSpec truth;
    const auto points = s3[0].observationPoints();
    for (int cells : {100, 160}) {
        const auto parameters = screwParameters(s3[0], truth.screw, cells);
        EXPECT_EQ(cutOnce.nut_path->fits(parameters, 2, cutOnce.motion.size(),
                                         cutOnce.ambient_C.size() - 1),
                  cells == 100);
        const auto a = simulateScrewRun(cutOnce, parameters, points);
        const auto b = simulateScrewRun(stepByStep, parameters, points);
        double worstError = 0, worstSensor = 0;
        for (std::size_t i = 0; i < points.size(); ++i)
            worstError = std::max(worstError, std::abs(a.error_um[i] - b.error_um[i]));
        ASSERT_FALSE(a.sensor_C.empty());
        for (std::size_t s = 0; s < a.sensor_C.size(); ++s)
            for (std::size_t j = 0; j < a.sensor_C[s].size(); ++j)
                worstSensor = std::max(worstSensor, std::abs(a.sensor_C[s][j] - b.sensor_C[s][j]));
        EXPECT_LT(worstError, 1e-9) << cells << " cells";
        EXPECT_LT(worstSensor, 1e-9) << cells << " cells";
    }
}
