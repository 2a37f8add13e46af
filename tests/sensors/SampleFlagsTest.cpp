// Leaving flagged samples out of a run: exactly the samples inside a range of
// their channel become NaN (missing to every model), counted once, and the
// ranges come from checkRun's findings.
#include <gtest/gtest.h>

#include <cmath>

#include "core/sensors/SampleFlags.h"

using namespace driftlab;
using namespace driftlab::sensors;

namespace {

Run runOf(std::size_t rows) {
    Run run;
    run.id = QStringLiteral("S1");
    run.samples.columns = {QStringLiteral("T_nut"), QStringLiteral("T_air")};
    run.samples.values.assign(2, {});
    for (std::size_t i = 0; i < rows; ++i) {
        run.samples.time_s.push_back(10.0 * double(i));
        run.samples.values[0].push_back(20 + 0.01 * double(i));
        run.samples.values[1].push_back(21 + 0.01 * double(i));
    }
    return run;
}

}  // namespace

TEST(SampleFlags, masksExactlyTheSamplesOfTheRangesChannelAndCountsEachOnce) {
    driftlab::Run run = runOf(100);
    run.samples.values[0][42] = std::numeric_limits<double>::quiet_NaN();  // already missing
    const driftlab::Run before = run;
    QStringList channels;
    const std::size_t masked = maskFlaggedSamples(
        run,
        {{QStringLiteral("T_nut"), SensorFault::OutOfRange, 400, 450},
         {QStringLiteral("T_nut"), SensorFault::Spike, 450, 450},   // overlaps: counted once
         {QStringLiteral("T_gone"), SensorFault::Frozen, 0, 990}},  // no such column
        &channels);
    EXPECT_EQ(masked, 5u);  // 400…450 s is six samples, one already missing
    EXPECT_EQ(channels, QStringList{QStringLiteral("T_nut")});
    for (std::size_t i = 0; i < 100; ++i) {
        const bool inside = i >= 40 && i <= 45;
        EXPECT_EQ(std::isnan(run.samples.values[0][i]), inside || i == 42) << i;
        if (!inside && i != 42) {
            EXPECT_EQ(run.samples.values[0][i], before.samples.values[0][i]);
        }
        EXPECT_EQ(run.samples.values[1][i], before.samples.values[1][i]);
    }
    EXPECT_EQ(run.samples.time_s, before.samples.time_s);
    EXPECT_EQ(maskFlaggedSamples(run, {}), 0u);
}

TEST(SampleFlags, rangesComeFromTheFindingsOfARunAndKindsRoundTripByName) {
    driftlab::Run run = runOf(200);
    for (std::size_t i = 50; i < 56; ++i) run.samples.values[1][i] = 900;  // open element
    Channel air;
    air.id = QStringLiteral("T_air");
    air.quantity = Quantity::Temperature;
    air.role = ChannelRole::Ambient;
    const auto checked = checkRun(run.samples, {air}, {}, SensorHealthSettings{});
    const std::vector<FlaggedRange> ranges = flaggedRanges(checked);
    ASSERT_EQ(ranges.size(), 1u);
    EXPECT_EQ(ranges[0],
              (FlaggedRange{QStringLiteral("T_air"), SensorFault::OutOfRange, 500, 550}));
    EXPECT_EQ(maskFlaggedSamples(run, ranges), 6u);
    for (SensorFault fault : kAllSensorFaults)
        EXPECT_EQ(sensorFaultFromString(toString(fault)), fault);
    EXPECT_FALSE(sensorFaultFromString(QStringLiteral("bad_luck")));
}
