// An adopted extension of heat-transfer running online: on a campaign of the
// simulated rig with motor heat hidden in it (made by the real CLI), live
// compensation with heat-transfer+motor_heat leaves less of the held-out
// run's thermal error than heat-transfer alone, and its cross-validation
// claims a narrower band. An extension that acts on the readings, or one the runs
// cannot support, is refused with the reason; a name that is no extension is
// a bad request before anything is fitted.
#include <gtest/gtest.h>

#include <QTemporaryDir>

#include "acquisition/live/LiveCompensationService.h"
#include "core/bundle/BundleReader.h"
#include "tests/support/CliRunner.h"

namespace driftlab::test {
namespace {

/// S1, S2 and S4 of the simulated rig with 0.5 W/(N·m)² of motor heat: two
/// moving states to tell the motor's heat from the nut's, one held out.
const Campaign& motorHeatCampaign() {
    static QTemporaryDir dir;
    static const Campaign campaign = [] {
        const QString bundle = dir.filePath(QStringLiteral("motor-heat"));
        const CliResult made = runCli({QStringLiteral("simulate"), QStringLiteral("--out"), bundle,
                                       QStringLiteral("--runs"), QStringLiteral("S1,S2,S4"),
                                       QStringLiteral("--effect"), QStringLiteral("motor_heat=0.5"),
                                       QStringLiteral("--seed"), QStringLiteral("5")});
        EXPECT_EQ(made.exitCode, 0) << made.err.constData();
        const bundle::BundleReadResult r = bundle::readBundle(bundle);
        EXPECT_TRUE(r.ok());
        return r.ok() ? *r.campaign : Campaign{};
    }();
    return campaign;
}

live::LiveCompensationOptions s4FromS1S2(const QString& model) {
    live::LiveCompensationOptions options;
    options.run = QStringLiteral("S4");
    options.train_runs = {QStringLiteral("S1"), QStringLiteral("S2")};
    options.model = model;
    // Every minute: with fewer updates, their delay hides what the model adds.
    options.update_interval_s = 60;
    return options;
}

struct Replayed {
    live::LivePlan plan;
    live::LiveRunResult result;
};

Replayed replay(const QString& model) {
    live::LiveCompensationOptions options = s4FromS1S2(model);
    QStringList labels;
    options.progress = [&](const QString& what, double) { labels << what; };
    Replayed r{live::planLive(motorHeatCampaign(), options), {}};
    EXPECT_EQ(labels, (QStringList{QStringLiteral("fitting ") + model,
                                   QStringLiteral("fitting ") + model}));
    r.result = live::runLive(r.plan, options);
    return r;
}

QString refusal(const QString& model) {
    try {
        live::planLive(motorHeatCampaign(), s4FromS1S2(model));
    } catch (const ServiceError& e) {
        return e.message();
    }
    return {};
}

}  // namespace

TEST(LiveExtension, motorHeatOnlineLeavesLessOfTheHeldOutErrorThanTheBaseModel) {
    const Replayed base = replay(QStringLiteral("heat-transfer"));
    const Replayed extended = replay(QStringLiteral("heat-transfer+motor_heat"));
    EXPECT_EQ(extended.plan.model(),
              QStringLiteral("the heat-transfer+motor_heat model fitted on S1,S2"));
    // The motor's heat reaches the screw late: the extension steps it online.
    EXPECT_TRUE(bool(extended.plan.online_inputs));
    EXPECT_FALSE(bool(base.plan.online_inputs));
    EXPECT_GT(extended.plan.screw.c_motor_W_per_Nm2, 0.1);
    EXPECT_EQ(base.plan.screw.c_motor_W_per_Nm2, 0);

    // Both replay the same run with the same updates' timing.
    ASSERT_EQ(extended.result.replay.updates.size(), base.result.replay.updates.size());
    EXPECT_DOUBLE_EQ(extended.result.replay.rms_before_um, base.result.replay.rms_before_um);
    EXPECT_LT(extended.result.replay.rms_after_um, 0.7 * base.result.replay.rms_after_um)
        << extended.result.replay.rms_after_um << " vs " << base.result.replay.rms_after_um;
    // Its own cross-validation knows it too, so it claims a narrower band.
    EXPECT_LT(extended.plan.validation.rms_um, base.plan.validation.rms_um);
    EXPECT_LT(extended.plan.uncertainty_um, base.plan.uncertainty_um);
    EXPECT_FALSE(extended.plan.validation.worseThanNone());
}

TEST(LiveExtension, anEffectOnTheReadingsIsRefusedWithItsReason) {
    const QString message = refusal(QStringLiteral("heat-transfer+air_refraction"));
    EXPECT_TRUE(message.contains(QStringLiteral("changes what is read"))) << qPrintable(message);
}

TEST(LiveExtension, aCauseTheRunsCannotSupportIsRefusedNamingWhatTheySupport) {
    const QString message = refusal(QStringLiteral("heat-transfer+sensor_offset:T_nut_9"));
    EXPECT_TRUE(message.contains(QStringLiteral("cannot support sensor_offset:T_nut_9")))
        << qPrintable(message);
    EXPECT_TRUE(message.contains(QStringLiteral("motor_heat"))) << qPrintable(message);
}

TEST(LiveExtension, aNameThatIsNoExtensionIsABadRequestBeforeAnyFit) {
    for (const QString& model : {QStringLiteral("mlr"), QStringLiteral("heat-transfer+"),
                                 QStringLiteral("heat-transfer++motor_heat")}) {
        live::LiveCompensationOptions options = s4FromS1S2(model);
        int calls = 0;
        options.progress = [&](const QString&, double) { ++calls; };
        try {
            live::planLive(motorHeatCampaign(), options);
            ADD_FAILURE() << qPrintable(model) << " was fitted";
        } catch (const ServiceError& e) {
            EXPECT_EQ(e.kind, ServiceError::Kind::BadRequest) << qPrintable(model);
            EXPECT_TRUE(e.message().contains(model)) << qPrintable(e.message());
        }
        EXPECT_EQ(calls, 0) << qPrintable(model);
    }
}

}  // namespace driftlab::test
