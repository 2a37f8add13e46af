// Holes in a logged channel are judged by the channel's own course on either
// side: bridged where a straight line through the hole stays within the
// channel's noise, left out (its observations not fitted or scored) where it
// cannot, and always reported.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/models/DataGaps.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"
#include "core/models/ThermalErrorData.h"
#include "tests/models/ModelTestSupport.h"

namespace driftlab::models {
namespace {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

/// A feed-axis run of 2 h sampled every 10 s with a nut and a room channel,
/// a pass every 600 s; `nut` and `room` give their temperatures.
Campaign campaignWith(const test::Profile& nut, const test::Profile& room) {
    Campaign c = test::feedAxisCampaign({{QStringLiteral("T_nut"), ChannelRole::Nut},
                                         {QStringLiteral("T_room"), ChannelRole::Ambient}});
    driftlab::Run run = test::sampledRun(c, QStringLiteral("S1"), 7200, 10,
                                         {{QStringLiteral("T_nut"), nut},
                                          {QStringLiteral("T_room"), room},
                                          {kFeedColumn, [](double) { return 0.0; }}});
    test::addPositioning(run, 600, 7200, [](double t, double x) { return 1e-5 * t * x; });
    c.runs.push_back(run);
    return c;
}

/// Blanks the channel's samples strictly between the two times.
void blank(Campaign& c, const QString& channel, double from_s, double to_s) {
    driftlab::Run& run = c.runs.front();
    std::vector<double>& v = run.samples.values[std::size_t(run.samples.columnIndex(channel))];
    for (std::size_t i = 0; i < v.size(); ++i)
        if (run.samples.time_s[i] > from_s && run.samples.time_s[i] < to_s) v[i] = kMissing;
}

const DataGap* gapOf(const RunData& run, const QString& channel) {
    for (const DataGap& g : run.gaps)
        if (g.channel == channel) return &g;
    return nullptr;
}

/// A slow room: a 0.3 K/h drift with 0.02 K of white noise, seeded.
test::Profile noisyRoom(unsigned seed) {
    auto rng = std::make_shared<std::mt19937>(seed);
    return [rng](double t) {
        std::normal_distribution<double> noise(0.0, 0.02);
        return 20 + 0.3 * t / 3600 + noise(*rng);
    };
}

TEST(DataGaps, aStraightChannelIsBridgedAndTheHoleReported) {
    Campaign c = campaignWith([](double t) { return 20 + t / 600; }, [](double) { return 20.0; });
    blank(c, QStringLiteral("T_nut"), 1000, 1300);
    const DatasetResult data = buildDataset(c, {QStringLiteral("S1")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    const RunData& run = data.runs.front();
    const DataGap* gap = gapOf(run, QStringLiteral("T_nut"));
    ASSERT_TRUE(gap);
    EXPECT_TRUE(gap->bridged);
    EXPECT_EQ(gap->run_id, QStringLiteral("S1"));
    EXPECT_DOUBLE_EQ(gap->from_s, 1000);
    EXPECT_DOUBLE_EQ(gap->to_s, 1300);
    EXPECT_NEAR(gap->bridge_error, 0, 1e-9);
    EXPECT_EQ(gap->observations_left_out, 0u);
    // Inside the hole the rise is the straight line, exactly (its zero is the
    // median of the first minute, at 30 s).
    EXPECT_NEAR(risesAt(run, {QStringLiteral("T_nut")}, {{1200, 0}})(0, 0), 1170.0 / 600, 1e-9);
    // Every observation is kept: cycle 1 at 600 s … cycle 12 at 7200 s.
    EXPECT_EQ(run.observations.size(), 12u * 16u);
    EXPECT_EQ(gapLines(run.gaps),
              QStringList{QStringLiteral("1 hole(s) in the log bridged, where the channel "
                                         "changes slowly against the hole (the longest 300 s): "
                                         "S1:T_nut")});
}

TEST(DataGaps, aChannelThatBendsInTheHoleIsLeftOutWithItsObservations) {
    // The nut warms until 1200 s, then holds: a bridge over 900 … 1500 s
    // would cut the corner by 0.25 K, far more than the (noiseless) channel allows.
    Campaign c = campaignWith([](double t) { return 20 + std::min(t, 1200.0) / 600; },
                              [](double) { return 20.0; });
    blank(c, QStringLiteral("T_nut"), 900, 1500);
    const DatasetResult data = buildDataset(c, {QStringLiteral("S1")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    const RunData& run = data.runs.front();
    const DataGap* gap = gapOf(run, QStringLiteral("T_nut"));
    ASSERT_TRUE(gap);
    EXPECT_FALSE(gap->bridged);
    EXPECT_NEAR(gap->bridge_error, 0.25, 0.01);
    // Cycle 2 at 1200 s falls in the hole: its 16 readings are left out.
    EXPECT_EQ(gap->observations_left_out, 16u);
    EXPECT_EQ(run.observations.size(), 11u * 16u);
    for (const ErrorObservation& o : run.observations) EXPECT_NE(o.time_s, 1200);
    try {
        risesAt(run, {QStringLiteral("T_nut")}, {{1200, 0}});
        ADD_FAILURE() << "a reading inside a hole left out was given";
    } catch (const ModelError& e) {
        EXPECT_EQ(e.message, QStringLiteral("run 'S1', channel 'T_nut': no sample between 900 s "
                                            "and 1500 s, a hole in the log that its course on "
                                            "either side does not let DriftLab bridge (its "
                                            "observations are left out)"));
    }
    // The simulation's inputs go on through the hole on the bridge: halfway
    // from 1.5 K to 2 K, less the 0.05 K of the first minute.
    EXPECT_NEAR(bridgedValueAt(run.temperatures.front().rise_K, 1200, run.run_id), 1.70, 1e-9);
    const QStringList lines = gapLines(run.gaps);
    ASSERT_EQ(lines.size(), 1);
    EXPECT_TRUE(lines.front().startsWith(QStringLiteral(
        "hole in the log left out: run 'S1', T_nut, 900–1500 s (a straight bridge could miss "
        "the channel's course by 0.25 K")))
        << qPrintable(lines.front());
    EXPECT_TRUE(lines.front().endsWith(QStringLiteral("16 observation(s) not fitted or scored")));
}

TEST(DataGaps, theSameHoleIsJudgedByEachChannelsOwnCourse) {
    // Three minutes without either channel, as a module outage leaves them:
    // the slow, noisy room is bridged; the nut, which turns from warming to
    // cooling inside the hole, is not.
    Campaign c = campaignWith(
        [](double t) { return 20 + (t < 2000 ? t / 300 : 2000.0 / 300 - (t - 2000) / 300); },
        noisyRoom(7));
    blank(c, QStringLiteral("T_nut"), 1900, 2100);
    blank(c, QStringLiteral("T_room"), 1900, 2100);
    const DatasetResult data = buildDataset(c, {QStringLiteral("S1")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    const RunData& run = data.runs.front();
    const DataGap* room = gapOf(run, QStringLiteral("T_room"));
    const DataGap* nut = gapOf(run, QStringLiteral("T_nut"));
    ASSERT_TRUE(room && nut);
    EXPECT_TRUE(room->bridged) << room->bridge_error << " K against " << room->tolerance;
    // Its tolerance is three times its noise (0.02 K), measured from the samples.
    EXPECT_NEAR(room->tolerance, 0.06, 0.015);
    EXPECT_FALSE(nut->bridged);
}

TEST(DataGaps, aChannelThatStopsBeforeTheRunEndsLeavesOutTheRest) {
    Campaign c = campaignWith([](double t) { return 20 + t / 600; }, [](double) { return 20.0; });
    blank(c, QStringLiteral("T_nut"), 5000, 1e9);
    const DatasetResult data = buildDataset(c, {QStringLiteral("S1")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    const RunData& run = data.runs.front();
    const DataGap* gap = gapOf(run, QStringLiteral("T_nut"));
    ASSERT_TRUE(gap);
    EXPECT_FALSE(gap->bridged);
    EXPECT_DOUBLE_EQ(gap->from_s, 5000);
    EXPECT_DOUBLE_EQ(gap->to_s, 7200);
    EXPECT_TRUE(gap->to_run_end);
    EXPECT_TRUE(std::isnan(gap->bridge_error));
    // Cycles 9 … 12 (5400 … 7200 s, the run's end) lie inside.
    EXPECT_EQ(gap->observations_left_out, 4u * 16u);
}

TEST(DataGaps, aLoggersOwnRhythmIsNoHoleButAMissedReadingIs) {
    // A thermometer read every 300 s: its rhythm is no outage …
    Campaign c = campaignWith([](double t) { return 20 + t / 600; }, [](double) { return 20.0; });
    std::vector<double>& nut = c.runs.front().samples.values[0];
    for (std::size_t i = 0; i < nut.size(); ++i)
        if (i % 30 != 0) nut[i] = kMissing;
    DatasetResult data = buildDataset(c, {QStringLiteral("S1")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    EXPECT_EQ(data.runs.front().temperatures.front().rise_K.sampling_s, 300);
    EXPECT_TRUE(data.runs.front().gaps.empty());
    // … three readings it missed (600 … 1200 s) are a hole of 1200 s, more
    // than three of its intervals: judged, and on a straight rise bridged.
    for (std::size_t i : {60, 90, 120}) nut[i] = kMissing;
    data = buildDataset(c, {QStringLiteral("S1")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    const DataGap* gap = gapOf(data.runs.front(), QStringLiteral("T_nut"));
    ASSERT_TRUE(gap);
    EXPECT_DOUBLE_EQ(gap->from_s, 300);
    EXPECT_DOUBLE_EQ(gap->to_s, 1500);
    EXPECT_TRUE(gap->bridged);
}

TEST(DataGaps, anAxisColumnIsBridgedOnlyWhereTheAxisRunsStraightThrough) {
    // The axis stands (feed 0) across one hole and changes speed inside another.
    Campaign c = campaignWith([](double t) { return 20 + t / 600; }, [](double) { return 20.0; });
    driftlab::Run& run = c.runs.front();
    std::vector<double>& feed =
        run.samples.values[std::size_t(run.samples.columnIndex(kFeedColumn))];
    for (std::size_t i = 0; i < feed.size(); ++i)
        feed[i] = run.samples.time_s[i] < 4000 ? 0.0 : 3000.0;
    blank(c, kFeedColumn, 1000, 1300);
    blank(c, kFeedColumn, 3900, 4100);
    const DatasetResult data = buildDataset(c, {QStringLiteral("S1")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    std::vector<const DataGap*> gaps;
    for (const DataGap& g : data.runs.front().gaps)
        if (g.channel == kFeedColumn) gaps.push_back(&g);
    ASSERT_EQ(gaps.size(), 2u);
    EXPECT_TRUE(gaps[0]->bridged);
    EXPECT_EQ(gaps[0]->unit, QStringLiteral("mm/min"));
    EXPECT_FALSE(gaps[1]->bridged);
}

TEST(DataGaps, aRunWhoseEveryObservationFallsInAHoleIsRefusedNamingIt) {
    Campaign c = campaignWith([](double t) { return 20 + std::min(t, 1200.0) / 600; },
                              [](double) { return 20.0; });
    blank(c, QStringLiteral("T_nut"), 300, 1e9);
    const DatasetResult data = buildDataset(c, {QStringLiteral("S1")});
    ASSERT_FALSE(data.ok());
    EXPECT_TRUE(data.error.startsWith(QStringLiteral(
        "run 'S1': every observation falls in a hole of the log that cannot be bridged "
        "(hole in the log left out: run 'S1', T_nut, 300–7200 s")))
        << qPrintable(data.error);
}

}  // namespace
}  // namespace driftlab::models
