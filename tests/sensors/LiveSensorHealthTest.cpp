// The live checker, fed sample by sample, gives every verdict within the
// spike half window, reports a frozen stretch's earlier samples as a backfill,
// and ends with the same flags and summary as the batch function.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "SensorHealthTestSupport.h"

using namespace driftlab;
using namespace driftlab::sensors;
using namespace driftlab::sensors::test;

TEST(LiveSensorHealth, sampleBySampleEqualsTheBatchAndLagsByTheHalfWindow) {
    SampleSeries series = cleanRun().samples;
    const QString id = QStringLiteral("T_bearing_fixed");
    auto& values = columnOf(series, id);
    values[rowAt(series, 600)] += 5;  // EMI
    for (std::size_t i = rowAt(series, 900); i < rowAt(series, 960); ++i)
        values[i] = 32767;  // open
    const std::size_t holdFrom = rowAt(series, 1500);
    for (std::size_t i = holdFrom; i <= rowAt(series, 2100); ++i) values[i] = values[holdFrom];
    values[rowAt(series, 2500)] = std::numeric_limits<double>::quiet_NaN();  // dropout

    const SensorHealthSettings settings;
    const auto half = static_cast<std::size_t>(settings.spike_half_window_samples);
    const Channel& channel = *cleanCampaign().findChannel(id);
    ChannelHealthChecker checker(id, channel.quantity,
                                 applicableChecks(channel.quantity, channel.role), settings);
    std::vector<SensorFlags> live(series.rowCount(), kNoFlags);
    std::vector<bool> seen(series.rowCount(), false);
    std::size_t backfills = 0;
    auto apply = [&](const HealthUpdate& update) {
        for (const auto& v : update.verdicts) {
            EXPECT_FALSE(seen[v.index]) << "verdict twice for " << v.index;
            seen[v.index] = true;
            live[v.index] |= v.flags;
        }
        if (update.backfill) {
            ++backfills;
            for (std::size_t i = update.backfill->first_index; i <= update.backfill->last_index;
                 ++i) {
                EXPECT_TRUE(seen[i]) << "backfill of a sample not yet final: " << i;
                live[i] |= bit(SensorFault::Frozen);
            }
        }
    };
    for (std::size_t i = 0; i < series.rowCount(); ++i) {
        apply(checker.push(series.time_s[i], values[i]));
        // Every sample older than the half window is final.
        if (i >= half) {
            EXPECT_TRUE(seen[i - half]) << i;
        }
    }
    apply(checker.finish());
    for (std::size_t i = 0; i < series.rowCount(); ++i) EXPECT_TRUE(seen[i]) << i;
    EXPECT_EQ(backfills, 1u);

    const ChannelHealth batch = checkColumn(series, channel, settings);
    EXPECT_EQ(live, batch.flags);
    const ChannelHealthSummary summary = checker.summary();
    EXPECT_EQ(summary.describe(), batch.summary.describe());
    EXPECT_EQ(summary.samples, series.rowCount());
    for (SensorFault fault : {SensorFault::OutOfRange, SensorFault::Frozen, SensorFault::Spike})
        EXPECT_NE(summary.finding(fault), nullptr) << toString(fault).toStdString();
    // The hold and the open block are not also taken for steps.
    EXPECT_EQ(summary.finding(SensorFault::RateOfChange), nullptr)
        << summary.describe().toStdString();
}

TEST(LiveSensorHealth, aDriftProbeOnlyGetsTheRangeCheck) {
    // A drift probe reads a constant while the spindle is cold: not frozen.
    SampleSeries series;
    series.columns = {QStringLiteral("D_x")};
    series.values.resize(1);
    for (int i = 0; i < 200; ++i) {
        series.time_s.push_back(10.0 * i);
        series.values[0].push_back(i == 150 ? 20'000.0 : (i > 100 ? 12.0 : 0.0));
    }
    const Channel probe{
        QStringLiteral("D_x"), Quantity::Displacement, ChannelRole::DriftX, {}, {}, {}};
    const ChannelHealth health = checkColumn(series, probe, SensorHealthSettings{});
    EXPECT_EQ(flaggedRows(health.flags), std::vector<std::size_t>{150});
    EXPECT_EQ(rowsWith(health.flags, SensorFault::OutOfRange), std::vector<std::size_t>{150});
}

TEST(LiveSensorHealth, theNutSensorGetsNoSpikeOrRateCheck) {
    // It rides over a screw that is kelvins warmer under the stroke than
    // beside it; frozen and out of range still apply.
    EXPECT_EQ(applicableChecks(Quantity::Temperature, ChannelRole::Nut),
              bit(SensorFault::OutOfRange) | bit(SensorFault::Frozen));
    EXPECT_TRUE(
        has(applicableChecks(Quantity::Temperature, ChannelRole::Bearing), SensorFault::Spike));
    SampleSeries series = cleanRun().samples;
    const Channel& nut = *cleanCampaign().findChannel(QStringLiteral("T_nut"));
    columnOf(series, nut.id)[100] = -242;
    EXPECT_EQ(
        rowsWith(checkColumn(series, nut, SensorHealthSettings{}).flags, SensorFault::OutOfRange),
        std::vector<std::size_t>{100});
}
