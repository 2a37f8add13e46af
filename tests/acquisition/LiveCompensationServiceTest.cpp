// The live compensation service itself (what `driftlab-cli live` and the
// GUI's Live page call): a simulated campaign's S3 replayed through the
// heat-transfer model fitted on S1, with the simulated controller over real
// Modbus TCP. Progress is reported, every update reaches the caller after the
// controller took it, a cancel stops between updates with nothing half-sent,
// and a model worse than no compensation never reaches a controller.
#include <gtest/gtest.h>

#include "acquisition/live/LiveCompensationService.h"
#include "core/bundle/BundleReader.h"
#include "tests/acquisition/PushTestSupport.h"
#include "tests/support/CliRunner.h"
#include "tests/support/SimulatedCampaign.h"

namespace driftlab::test {

/// S1 and S3 of the simulated rig, read once per test binary.
const Campaign& twoStates() {
    return readSimulatedCampaign(QStringLiteral("S1,S3"), 5);
}

live::LiveCompensationOptions s3FromS1() {
    live::LiveCompensationOptions options;
    options.run = QStringLiteral("S3");
    options.train_runs = {QStringLiteral("S1")};
    options.update_interval_s = 300;
    return options;
}

/// The controller's live offset (block 3), µm.
double liveOffsetUm(const sim::SimulatedController& c) {
    const std::uint16_t words[2] = {c.registerValue(2001), c.registerValue(2002)};
    return push::getInt32(words) / 1000.0;
}

TEST(LiveCompensationService, reportsTheFitsProgressAndEveryUpdateTheControllerTook) {
    auto controller = startController();
    live::LiveCompensationOptions options = s3FromS1();
    options.controller = urlOf(*controller);
    std::vector<double> fractions;
    options.progress = [&](const QString& what, double fraction) {
        EXPECT_EQ(what, QStringLiteral("fitting heat-transfer"));
        fractions.push_back(fraction);
    };
    std::vector<compensation::LiveUpdate> seen;
    options.on_update = [&](const compensation::LiveUpdate& u) {
        // Reported after the controller took it: its registers hold it already.
        EXPECT_NEAR(liveOffsetUm(*controller), u.offset_um, 1e-3);
        seen.push_back(u);
    };
    const live::LivePlan plan = live::planLive(twoStates(), options);
    EXPECT_EQ(fractions, (std::vector<double>{0, 1}));
    EXPECT_FALSE(plan.validation.worseThanNone());
    const live::LiveRunResult result = live::runLive(plan, options);
    ASSERT_GT(result.replay.updates.size(), 3u);
    EXPECT_EQ(seen.size(), result.replay.updates.size());
    EXPECT_EQ(result.written, int(seen.size()));
    EXPECT_EQ(controller->registerValue(2000), seen.size());  // one sequence per update
    EXPECT_TRUE(result.controller_error.isEmpty());
    EXPECT_GT(result.reduction(), 0.5);
}

TEST(LiveCompensationService, aCancelStopsBetweenUpdatesWithEveryReportedUpdateSent) {
    auto controller = startController();
    live::LiveCompensationOptions options = s3FromS1();
    options.controller = urlOf(*controller);
    std::size_t seen = 0;
    options.on_update = [&](const compensation::LiveUpdate&) { ++seen; };
    options.cancelled = [&] { return seen >= 2; };
    const live::LivePlan plan = live::planLive(twoStates(), options);
    const live::LiveRunResult result = live::runLive(plan, options);
    EXPECT_TRUE(result.replay.cancelled);
    EXPECT_EQ(result.replay.updates.size(), 2u);
    EXPECT_EQ(result.written, 2);
    EXPECT_EQ(controller->registerValue(2000), 2);
    EXPECT_NEAR(liveOffsetUm(*controller), result.replay.updates.back().offset_um, 1e-3);
}

TEST(LiveCompensationService, aCancelDuringTheFitStopsBeforeAnyReplay) {
    live::LiveCompensationOptions options = s3FromS1();
    options.cancelled = [] { return true; };
    try {
        live::planLive(twoStates(), options);
        FAIL() << "a cancelled fit gave a plan";
    } catch (const ServiceError& e) {
        EXPECT_EQ(e.message(), QStringLiteral("the fit was cancelled"));
    }
}

TEST(LiveCompensationService, aModelWorseThanNoneIsRefusedBeforeTheControllerIsWritten) {
    auto controller = startController();
    live::LiveCompensationOptions options = s3FromS1();
    options.controller = urlOf(*controller);
    live::LivePlan plan = live::planLive(twoStates(), options);
    // The same plan judged worse than none by its cross-validation.
    plan.validation.rms_um = plan.validation.none_rms_um * 2;
    ASSERT_TRUE(plan.validation.worseThanNone());
    try {
        live::runLive(plan, options);
        FAIL() << "a harmful model was sent";
    } catch (const ServiceError& e) {
        EXPECT_EQ(e.kind, ServiceError::Kind::BadRequest);
        EXPECT_TRUE(e.message().contains(QStringLiteral("worse than no compensation"))) << e.what();
    }
    EXPECT_EQ(controller->writeRequests(), 0);
    options.override_no_harm = true;
    EXPECT_GT(live::runLive(plan, options).written, 0);
}

TEST(LiveCompensationService, overlappingRunsAreABadRequest) {
    live::LiveCompensationOptions options = s3FromS1();
    options.train_runs << QStringLiteral("S3");
    try {
        live::planLive(twoStates(), options);
        FAIL();
    } catch (const ServiceError& e) {
        EXPECT_EQ(e.kind, ServiceError::Kind::BadRequest);
        EXPECT_TRUE(e.message().contains(QStringLiteral("S3"))) << e.what();
    }
}

}  // namespace driftlab::test
