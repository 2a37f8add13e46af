// The model data: thermal error referenced to the cold cycle, temperature rises
// referenced to the run's start, and a clear error for every kind of bad data.

#include <gtest/gtest.h>
#include <cmath>
#include <limits>

#include "core/domain/Median.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"
#include "core/models/ThermalErrorData.h"
#include "tests/models/ModelTestSupport.h"

namespace driftlab::models {
namespace {

using test::addPositioning;
using test::feedAxisCampaign;
using test::sampledRun;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Campaign nutOnlyCampaign() {
    Campaign c = feedAxisCampaign({{QStringLiteral("T_nut"), ChannelRole::Nut}});
    driftlab::Run run =
        sampledRun(c, QStringLiteral("S1"), 3600, 10,
                   {{QStringLiteral("T_nut"), [](double t) { return 20 + t / 600; }}});
    addPositioning(run, 600, 3600, [](double t, double x) { return 1e-5 * t * x; });
    c.runs.push_back(run);
    return c;
}

QString errorOf(const Campaign& c, const QStringList& runs, const DatasetOptions& options = {}) {
    const DatasetResult result = buildDataset(c, runs, options);
    EXPECT_FALSE(result.ok());
    return result.error;
}

TEST(ThermalErrorData, positioningErrorIsTheDeviationMinusCycleZero) {
    const DatasetResult data = buildDataset(nutOnlyCampaign(), {QStringLiteral("S1")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    const RunData& run = data.runs.front();
    ASSERT_EQ(run.observations.size(), 6u * 16u);  // cycles 1..6, 8 targets, 2 directions
    for (const ErrorObservation& o : run.observations) {
        EXPECT_GE(o.cycle, 1);
        EXPECT_DOUBLE_EQ(o.time_s, 600.0 * o.cycle);
        // The cold geometric error and the backlash are gone, the same for both directions.
        EXPECT_NEAR(o.error_um, 1e-5 * o.time_s * o.position_mm, 1e-12);
    }
    EXPECT_TRUE(run.positionDependent());
    EXPECT_DOUBLE_EQ(run.fixedEnd_mm(), test::kFixedEndMm);
    ASSERT_TRUE(run.lead_mm());
    EXPECT_DOUBLE_EQ(*run.lead_mm(), test::kLeadMm);
}

TEST(ThermalErrorData, riseIsReferencedToTheMedianOfTheFirstMinute) {
    Campaign c = nutOnlyCampaign();
    // A spike in the very first sample must not shift every rise of the run.
    c.runs.front().samples.values[0][0] = 35;
    const DatasetResult data = buildDataset(c, {QStringLiteral("S1")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    const RunData& run = data.runs.front();
    // Samples at 10..60 s read 20 + t/600, the one at 0 s 35: the median is the 40 s sample.
    EXPECT_NEAR(run.temperatures.front().reference_C, 20 + 40.0 / 600, 1e-12);
    const Eigen::MatrixXd rises = risesAt(run, {QStringLiteral("T_nut")}, {{1234.5, 0}});
    EXPECT_NEAR(rises(0, 0), (1234.5 - 40) / 600, 1e-12);  // between samples: interpolated
}

TEST(ThermalErrorData, keepsAxisSignalsAndMotion) {
    Campaign c = nutOnlyCampaign();
    driftlab::Run& run = c.runs.front();
    run.samples.values[std::size_t(run.samples.columnIndex(kFeedColumn))].assign(
        run.samples.rowCount(), 8000);
    run.motion.push_back({0, 2.1, 210, 490, 8000});
    const DatasetResult data = buildDataset(c, {QStringLiteral("S1")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    EXPECT_EQ(data.runs.front().feed_mm_min.value.size(), run.samples.rowCount());
    EXPECT_TRUE(data.runs.front().torque_Nm.empty());  // logged as missing throughout
    EXPECT_EQ(data.runs.front().motion.size(), 1u);
}

TEST(ThermalErrorData, driftTargetIsTheChannelMinusTheMedianOfItsFirstMinute) {
    Campaign c = feedAxisCampaign({{QStringLiteral("T_spindle"), ChannelRole::Spindle}});
    c.channels.push_back(
        {QStringLiteral("D_x"), Quantity::Displacement, ChannelRole::DriftX, {}, {}, {}});
    c.sample_columns.push_back(QStringLiteral("D_x"));
    driftlab::Run run = sampledRun(c, QStringLiteral("SP1"), 600, 10,
                                   {{QStringLiteral("T_spindle"), [](double) { return 21.0; }},
                                    {QStringLiteral("D_x"), [](double t) { return 3 + t / 60; }}});
    run.kind = RunKind::Spindle;
    // The probe's noise on its first reading: the zero of every later error
    // of the run if that reading alone were the zero.
    run.samples.values[std::size_t(run.samples.columnIndex(QStringLiteral("D_x")))][0] = 3.4;
    c.runs.push_back(run);

    EXPECT_TRUE(errorOf(c, {QStringLiteral("SP1")})
                    .contains(QStringLiteral("run 'SP1' is a spindle run: its thermal error is in "
                                             "its displacement channels; choose one as the "
                                             "target (D_x)")));
    DatasetOptions options;
    options.target_channel = QStringLiteral("D_x");
    const DatasetResult data = buildDataset(c, {QStringLiteral("SP1")}, options);
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    const RunData& sp1 = data.runs.front();
    EXPECT_FALSE(sp1.positionDependent());
    ASSERT_EQ(sp1.observations.size(), 61u);  // every sample, 0 … 600 s
    // 0–60 s read 3.4, then 3 + t/60 from 10 s: their median is the 30 s reading, 3.5.
    EXPECT_DOUBLE_EQ(sp1.observations.front().time_s, 0);
    EXPECT_NEAR(sp1.observations.front().error_um, -0.1, 1e-12);
    EXPECT_NEAR(sp1.observations[6].error_um, 0.5, 1e-12);  // at 60 s
    EXPECT_NEAR(sp1.observations.back().error_um, 9.5, 1e-12);

    // The window is the dataset's reference window, as for a temperature rise.
    options.reference_window_s = 0;
    const DatasetResult firstOnly = buildDataset(c, {QStringLiteral("SP1")}, options);
    ASSERT_TRUE(firstOnly.ok()) << qPrintable(firstOnly.error);
    EXPECT_NEAR(firstOnly.runs.front().observations.back().error_um, 13 - 3.4, 1e-12);
}

TEST(ThermalErrorData, theZeroIsTheMedianOfTheFirstMinuteWhateverItsCount) {
    // Twelve readings in a minute at 5 s, six at 10 s: an even count's zero is
    // the mean of the middle two, in any order; a spike does not move it.
    EXPECT_DOUBLE_EQ(median({3.5, 3.4, 9.0, 3.6}), 3.55);
    EXPECT_DOUBLE_EQ(median({3.6, 3.4, 3.5}), 3.5);
    EXPECT_DOUBLE_EQ(median({2.0}), 2.0);
    EXPECT_TRUE(std::isnan(median({})));
}

TEST(ThermalErrorData, runWithoutPositioningDataIsAnError) {
    Campaign c = nutOnlyCampaign();
    driftlab::Run s2 = c.runs.front();
    s2.id = QStringLiteral("S2");
    s2.positioning.clear();
    c.runs.push_back(s2);
    EXPECT_EQ(errorOf(c, {QStringLiteral("S1"), QStringLiteral("S2")}),
              QStringLiteral("run 'S2' has no positioning measurements (positioning.csv): its "
                             "thermal error is unknown"));
}

TEST(ThermalErrorData, runWithoutCycleZeroIsAnError) {
    Campaign c = nutOnlyCampaign();
    std::erase_if(c.runs.front().positioning,
                  [](const PositioningMeasurement& m) { return m.cycle == 0; });
    EXPECT_EQ(errorOf(c, {QStringLiteral("S1")}),
              QStringLiteral("run 'S1' has no cycle 0 (the cold reference) in its positioning "
                             "measurements"));
}

TEST(ThermalErrorData, targetMissingFromCycleZeroIsAnError) {
    Campaign c = nutOnlyCampaign();
    c.runs.front().positioning.push_back({1200, 2, 750, Direction::Positive, 1.0});
    EXPECT_EQ(errorOf(c, {QStringLiteral("S1")}),
              QStringLiteral("run 'S1': cycle 2 measures target 750 mm (+) but cycle 0 does not, "
                             "so it has no cold reference"));
}

TEST(ThermalErrorData, nanDeviationIsAnError) {
    Campaign c = nutOnlyCampaign();
    c.runs.front().positioning[20].deviation_um = kNaN;
    EXPECT_EQ(errorOf(c, {QStringLiteral("S1")}),
              QStringLiteral("run 'S1': positioning measurement 21 (cycle 1) has a NaN or "
                             "infinite time, target or deviation"));
}

TEST(ThermalErrorData, infiniteSampleIsAnError) {
    Campaign c = nutOnlyCampaign();
    c.runs.front().samples.values[0][30] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(errorOf(c, {QStringLiteral("S1")}),
              QStringLiteral("run 'S1', channel 'T_nut': infinite value at t = 300 s"));
}

TEST(ThermalErrorData, unknownOrRepeatedRunIsAnError) {
    const Campaign c = nutOnlyCampaign();
    EXPECT_EQ(errorOf(c, {QStringLiteral("S9")}),
              QStringLiteral("run 'S9' is not in campaign 'synthetic feed axis'"));
    EXPECT_EQ(errorOf(c, {QStringLiteral("S1"), QStringLiteral("S1")}),
              QStringLiteral("run 'S1' is selected twice"));
    EXPECT_EQ(errorOf(c, {}), QStringLiteral("no runs selected"));
}

TEST(ThermalErrorData, targetMustBeADisplacementChannel) {
    DatasetOptions options;
    options.target_channel = QStringLiteral("T_nut");
    EXPECT_TRUE(errorOf(nutOnlyCampaign(), {QStringLiteral("S1")}, options)
                    .startsWith(QStringLiteral("target channel 'T_nut' is a temperature channel; "
                                               "a target must be a displacement channel")));
}

TEST(ThermalErrorData, channelStartingLateHasNoReference) {
    Campaign c = nutOnlyCampaign();
    std::vector<double>& nut = c.runs.front().samples.values[0];
    for (std::size_t i = 0; i < 50; ++i) nut[i] = kNaN;
    const DatasetResult data = buildDataset(c, {QStringLiteral("S1")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    EXPECT_EQ(data.runs.front().temperatures.front().unusable,
              QStringLiteral("run 'S1', channel 'T_nut': first sample at 500 s, too late for a "
                             "reference at the run's start (limit 120 s)"));
}

}  // namespace
}  // namespace driftlab::models
