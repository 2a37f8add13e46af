// Where a held-out run's temperatures leave the training runs' (issue 10):
// the envelope on hand-made runs, then on a campaign of the independent
// spindle simulator (seed 64) whose training runs all warmed the room by about
// 1 K and whose held-out P4 and P5 ran in a cooling room, read by the library
// and by `driftlab-cli fit` as a user runs it.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonObject>

#include "core/bundle/BundleReader.h"
#include "core/models/TrainingEnvelope.h"
#include "tests/support/CliRunner.h"

namespace driftlab::models {
namespace {

/// A rise that goes linearly from 0 to `end_K` over an hour.
TemperatureRise linearRise(const QString& id, ChannelRole role, double end_K) {
    TemperatureRise t;
    t.channel_id = id;
    t.role = role;
    for (int i = 0; i <= 60; ++i) {
        t.rise_K.time_s.push_back(60.0 * i);
        t.rise_K.value.push_back(end_K * i / 60.0);
    }
    return t;
}

RunData runWith(const QString& id, double room_K, double spindle_K) {
    RunData run;
    run.run_id = id;
    run.temperatures = {linearRise(QStringLiteral("T_room"), ChannelRole::Ambient, room_K),
                        linearRise(QStringLiteral("T_sp"), ChannelRole::Spindle, spindle_K)};
    return run;
}

TEST(TrainingEnvelope, reportsARiseBeyondTheTrainingRangeByMoreThanItsMargin) {
    const std::vector<RunData> training{runWith("A", 1.0, 5.0), runWith("B", 0.6, 4.0)};
    // Room falling by 0.5 K: 0.5 K below a range of 0 … +1 K, past its 0.1 K
    // margin. The spindle 0.3 K above +5 K: within its margin (a tenth of 5 K).
    // The third run goes 0.8 K beyond on the spindle and 0.3 K on the room.
    const std::vector<RunData> heldOut{runWith("C", -0.5, 5.3), runWith("D", 1.3, 5.8)};
    const std::vector<RiseBeyondTraining> beyond = risesBeyondTraining(training, heldOut);
    ASSERT_EQ(beyond.size(), 3u);
    EXPECT_EQ(beyond[0].run, QStringLiteral("C"));
    EXPECT_EQ(beyond[0].channel, QStringLiteral("T_room"));
    EXPECT_EQ(beyond[0].role, ChannelRole::Ambient);
    EXPECT_DOUBLE_EQ(beyond[0].rise_K, -0.5);
    EXPECT_DOUBLE_EQ(beyond[0].training_low_K, 0.0);
    EXPECT_DOUBLE_EQ(beyond[0].training_high_K, 1.0);
    // Within D, the furthest in ranges first: the room 0.3 K beyond a 1 K
    // range before the spindle 0.8 K beyond a 5 K range.
    EXPECT_EQ(beyond[1].run, QStringLiteral("D"));
    EXPECT_EQ(beyond[1].channel, QStringLiteral("T_room"));
    EXPECT_EQ(beyond[2].channel, QStringLiteral("T_sp"));
    EXPECT_DOUBLE_EQ(beyond[2].rise_K, 5.8);
    EXPECT_EQ(describeRisesBeyondTraining(beyond),
              QStringList({QStringLiteral("C: T_room (ambient) −0.50 K (training runs +0.00 K … "
                                          "+1.00 K)"),
                           QStringLiteral("D: T_room (ambient) +1.30 K (training runs +0.00 K … "
                                          "+1.00 K), T_sp (spindle) +5.80 K (training runs "
                                          "+0.00 K … +5.00 K)")}));
    // Inside the range, nothing; a channel one training run cannot give is
    // left out rather than judged on the others.
    EXPECT_TRUE(risesBeyondTraining(training, {runWith("E", 0.5, 4.5)}).empty());
    std::vector<RunData> oneUnusable = training;
    oneUnusable[1].temperatures[0].unusable = QStringLiteral("no samples");
    const auto withoutRoom = risesBeyondTraining(oneUnusable, heldOut);
    ASSERT_EQ(withoutRoom.size(), 1u);
    EXPECT_EQ(withoutRoom[0].channel, QStringLiteral("T_sp"));
}

QString roomCampaign() {
    return QStringLiteral(DRIFTLAB_INDEPENDENT_SPINDLE_ROOM "/seed-64");
}

TEST(TrainingEnvelope, aSpindleSpeedBeyondTheTrainingSpeedsIsAnExtrapolation) {
    // Runs at constant speeds after a stop: 1250, 2500 and 3750 rpm to train.
    auto atSpeed = [](const QString& id, double rpm) {
        RunData run = runWith(id, 0.5, 3);
        run.spindle_speed_rpm.name = QStringLiteral("S");
        run.spindle_speed_rpm.time_s = {0, 60, 3600};
        run.spindle_speed_rpm.value = {0, rpm, rpm};
        return run;
    };
    const std::vector<RunData> training{atSpeed("R1250", 1250), atSpeed("R2500", 2500),
                                        atSpeed("R3750", 3750)};
    // 4000 rpm is within a tenth of the 0 … 3750 rpm range; 5000 is not.
    const auto beyond =
        speedsBeyondTraining(training, {atSpeed("R4000", 4000), atSpeed("R5000", 5000)});
    ASSERT_EQ(beyond.size(), 1u);
    EXPECT_EQ(beyond[0].run, QStringLiteral("R5000"));
    EXPECT_DOUBLE_EQ(beyond[0].speed_rpm, 5000);
    EXPECT_EQ(describeSpeedsBeyondTraining(beyond),
              QStringList{QStringLiteral(
                  "R5000: S (spindle speed) 5000 rpm (training runs 0 … 3750 rpm)")});
    // The same temperatures: no rise is beyond, the speed alone says it.
    EXPECT_TRUE(risesBeyondTraining(training, {atSpeed("R5000", 5000)}).empty());
    // A training run without a speed log: nothing to compare.
    std::vector<RunData> unlogged = training;
    unlogged[1].spindle_speed_rpm = {};
    EXPECT_TRUE(speedsBeyondTraining(unlogged, {atSpeed("R5000", 5000)}).empty());
}

TEST(TrainingEnvelope, namesTheRoomWhereHeldOutRunsCooledAndEveryTrainingRunWarmed) {
    const bundle::BundleReadResult read = bundle::readBundle(roomCampaign());
    ASSERT_TRUE(read.ok()) << qPrintable(read.error->toString());
    DatasetOptions options;
    options.target_channel = QStringLiteral("Z1");
    const DatasetResult train = buildDataset(*read.campaign, {"P1", "P2", "P3"}, options);
    const DatasetResult test = buildDataset(*read.campaign, {"P4", "P5", "P6"}, options);
    ASSERT_TRUE(train.ok() && test.ok()) << qPrintable(train.error + test.error);
    const std::vector<RiseBeyondTraining> beyond = risesBeyondTraining(train.runs, test.runs);
    ASSERT_FALSE(beyond.empty());
    // The room sensor is what P4 leaves furthest: it fell by about 1 K where
    // every training run's rose by about 1 K (the simulator's own draw; the
    // column and base, which follow the room, fell with it).
    EXPECT_EQ(beyond.front().run, QStringLiteral("P4"));
    EXPECT_EQ(beyond.front().channel, QStringLiteral("TC15"));
    EXPECT_EQ(beyond.front().role, ChannelRole::Ambient);
    EXPECT_LT(beyond.front().rise_K, -0.7);
    EXPECT_GT(beyond.front().training_high_K, 0.9);
    bool p5Room = false;
    for (const RiseBeyondTraining& b : beyond) {
        EXPECT_NE(b.run, QStringLiteral("P6")) << qPrintable(b.channel);  // room +0.3 K: within
        p5Room = p5Room || (b.run == QStringLiteral("P5") && b.channel == QStringLiteral("TC15"));
    }
    EXPECT_TRUE(p5Room);
}

TEST(TrainingEnvelope, fitOnTheCommandLineSaysWhereItsHeldOutScoreIsAnExtrapolation) {
    const QStringList fit{QStringLiteral("fit"),      roomCampaign(),
                          QStringLiteral("--model"),  QStringLiteral("mlr"),
                          QStringLiteral("--train"),  QStringLiteral("P1,P2,P3"),
                          QStringLiteral("--test"),   QStringLiteral("P4,P5,P6"),
                          QStringLiteral("--target"), QStringLiteral("Z1")};
    const test::CliResult text = test::runCli(fit);
    ASSERT_EQ(text.exitCode, 0) << text.err.constData();
    EXPECT_TRUE(text.out.contains("beyond the training runs' temperature rises"));
    EXPECT_TRUE(text.out.contains("  P4: TC15 (ambient) −")) << text.out.constData();

    const test::CliResult json = test::runCli(QStringList(fit) << QStringLiteral("--json"));
    ASSERT_EQ(json.exitCode, 0) << json.err.constData();
    const QJsonArray beyond = test::json(json)[QStringLiteral("beyond_training")].toArray();
    ASSERT_FALSE(beyond.isEmpty());
    const QJsonObject first = beyond.first().toObject();
    EXPECT_EQ(first[QStringLiteral("run")].toString(), QStringLiteral("P4"));
    EXPECT_EQ(first[QStringLiteral("channel")].toString(), QStringLiteral("TC15"));
    EXPECT_EQ(first[QStringLiteral("role")].toString(), QStringLiteral("ambient"));
    EXPECT_LT(first[QStringLiteral("rise_K")].toDouble(), -0.7);

    // A training score has nothing held out to be beyond.
    const test::CliResult trainingOnly =
        test::runCli(QStringList(fit.mid(0, 6))
                     << QStringLiteral("--test") << QString() << QStringLiteral("--target")
                     << QStringLiteral("Z1") << QStringLiteral("--json"));
    ASSERT_EQ(trainingOnly.exitCode, 0) << trainingOnly.err.constData();
    EXPECT_TRUE(test::json(trainingOnly)[QStringLiteral("beyond_training")].toArray().isEmpty());
}

}  // namespace
}  // namespace driftlab::models
