// The services the command line and the GUI share, called directly: the
// held-out fit, a batch item's analyses and the thermal profile of a
// compensation table, on a simulated campaign made by the real CLI. Each
// reports its progress, and a cancel stops it early with nothing returned
// half-done.
#include <gtest/gtest.h>

#include <QJsonArray>

#include "core/bundle/BundleReader.h"
#include "core/compensation/ThermalProfile.h"
#include "db/BatchAnalysis.h"
#include "db/HeldOutFit.h"
#include "tests/support/CliRunner.h"
#include "tests/support/SimulatedCampaign.h"

namespace driftlab::test {

/// S1 and S3 of the simulated rig, read once per test binary.
const Campaign& servicesCampaign() {
    return readSimulatedCampaign(QStringLiteral("S1,S3"), 5);
}

TEST(HeldOutFitService, fitsOnTheFirstRunScoresTheOtherAndReportsProgress) {
    db::HeldOutFitOptions options;
    options.model = QStringLiteral("heat-transfer");
    std::vector<double> fractions;
    options.progress = [&](const QString& what, double fraction) {
        EXPECT_EQ(what, QStringLiteral("fitting heat-transfer"));
        fractions.push_back(fraction);
    };
    const db::HeldOutFit fit = db::fitHeldOut(servicesCampaign(), options);
    EXPECT_EQ(fractions, (std::vector<double>{0, 1}));
    EXPECT_EQ(fit.trainRuns, QStringList{QStringLiteral("S1")});
    EXPECT_EQ(fit.testRuns, QStringList{QStringLiteral("S3")});
    EXPECT_GT(fit.score.reduction, 0.5);
    EXPECT_EQ(fit.record.train_runs, fit.trainRuns);
}

TEST(HeldOutFitService, anUnknownModelIsABadRequestAndACancelStopsTheFit) {
    db::HeldOutFitOptions options;
    options.model = QStringLiteral("no-such-model");
    try {
        db::fitHeldOut(servicesCampaign(), options);
        FAIL();
    } catch (const ServiceError& e) {
        EXPECT_EQ(e.kind, ServiceError::Kind::BadRequest);
        EXPECT_TRUE(e.message().contains(QStringLiteral("no-such-model"))) << e.what();
    }
    options.model = QStringLiteral("heat-transfer");
    options.cancelled = [] { return true; };
    try {
        db::fitHeldOut(servicesCampaign(), options);
        FAIL() << "a cancelled fit returned";
    } catch (const ServiceError& e) {
        EXPECT_EQ(e.message(), QStringLiteral("the fit was cancelled"));
    }
}

TEST(BatchAnalysisService, runsTheAnalysesAskedForInOrderAndStopsWhenCancelled) {
    db::BatchAnalysisOptions options;
    options.analyses = {db::kAnalysisInfo, db::kAnalysisIso230_2, db::kAnalysisFit};
    QStringList started;
    options.progress = [&](const QString& what, double) { started << what; };
    const db::BatchAnalysis all = db::analyseCampaign(servicesCampaign(), options);
    EXPECT_TRUE(all.ok()) << qPrintable(all.errors.join(QStringLiteral("; ")));
    EXPECT_EQ(started, (QStringList{db::kAnalysisIso230_2, db::kAnalysisFit}));
    // Two positioning runs: ISO 230-2 has no default run and says why.
    EXPECT_TRUE(all.json[QStringLiteral("iso230_2")].isNull());
    EXPECT_TRUE(all.json[QStringLiteral("skipped")][QStringLiteral("iso230_2")].isString());
    EXPECT_TRUE(all.json[QStringLiteral("fit")].isObject());
    EXPECT_TRUE(all.json[QStringLiteral("channels")].isArray());
    EXPECT_FALSE(all.json.contains(QStringLiteral("diagnosis")));

    // Cancelled once the ISO 230-2 evaluation began: the fit never starts.
    options.cancelled = [&] { return !started.isEmpty(); };
    started.clear();
    const db::BatchAnalysis stopped = db::analyseCampaign(servicesCampaign(), options);
    EXPECT_TRUE(stopped.cancelled);
    EXPECT_FALSE(stopped.ok());
    EXPECT_EQ(started, QStringList{db::kAnalysisIso230_2});
    EXPECT_FALSE(stopped.json.contains(QStringLiteral("fit")));
}

TEST(ThermalProfileService, theProfileAtAStateFollowsTheFittedModel) {
    compensation::ThermalStateOptions options;
    options.model = QStringLiteral("heat-transfer");
    options.state_run = QStringLiteral("S3");
    options.time_s = 3600;
    options.train_runs = {compensation::defaultTrainingRun(servicesCampaign(), options.state_run)};
    EXPECT_EQ(options.train_runs, QStringList{QStringLiteral("S1")});
    int reports = 0;
    options.progress = [&](const QString&, double) { ++reports; };
    const compensation::ThermalStateFit fit =
        compensation::fitThermalState(servicesCampaign(), options);
    EXPECT_EQ(reports, 2);
    EXPECT_TRUE(fit.choseNone().isEmpty());
    const compensation::ThermalProfile profile = compensation::thermalProfile(fit, 0, 700);
    // An hour into S3 the screw has grown: the error differs along the axis.
    EXPECT_GT(std::abs(profile.error_um(700) - profile.error_um(0)), 1.0);
    EXPECT_EQ(profile.description, QStringLiteral("heat-transfer fitted on S1, at S3 t = 3600 s"));

    options.time_s = 1e9;  // after the run's end: the request is wrong, not the data
    try {
        compensation::fitThermalState(servicesCampaign(), options);
        FAIL();
    } catch (const ServiceError& e) {
        EXPECT_EQ(e.kind, ServiceError::Kind::BadRequest);
        EXPECT_TRUE(e.message().startsWith(QStringLiteral("run S3 ends at"))) << e.what();
    }
}

}  // namespace driftlab::test
