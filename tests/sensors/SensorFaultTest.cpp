// Clean data of the simulated rig raises no flag; each injected fault is
// flagged at the injected samples and nowhere else, and the summary names the
// channel, the kind and the time range.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "SensorHealthTestSupport.h"
#include "core/bundle/BundleReader.h"
#include "core/rig/CampaignSimulator.h"

using namespace driftlab;
using namespace driftlab::sensors;
using namespace driftlab::sensors::test;

namespace {

const SensorHealthSettings kDefaults;

ChannelHealth checkTemperature(const SampleSeries& series, const QString& id) {
    return checkColumn(series, *cleanCampaign().findChannel(id), kDefaults);
}

/// The finding of `fault` in `summary`, after checking it is the only one.
const FaultFinding& onlyFinding(const ChannelHealthSummary& summary, SensorFault fault) {
    EXPECT_EQ(summary.findings.size(), 1u) << summary.describe().toStdString();
    const FaultFinding* finding = summary.finding(fault);
    if (!finding) throw std::runtime_error("no " + toString(fault).toStdString() + " finding");
    return *finding;
}

}  // namespace

TEST(SensorHealth, cleanRigDataRaisesNoFlag) {
    const Campaign& campaign = cleanCampaign();
    const driftlab::Run& run = cleanRun();
    ASSERT_GT(run.samples.rowCount(), 500u);
    const auto health = checkRun(run.samples, campaign.channels, {}, kDefaults);
    ASSERT_GE(health.size(), 6u);
    for (const auto& [id, channel] : health) {
        SCOPED_TRACE(id.toStdString());
        EXPECT_TRUE(flaggedRows(channel.flags).empty()) << channel.summary.describe().toStdString();
        EXPECT_TRUE(channel.summary.healthy());
        EXPECT_EQ(channel.summary.samples, run.samples.rowCount());
    }
}

TEST(SensorHealth, otherNoiseSeedsAndDropoutsRaiseNoFlagEither) {
    // A false alarm rate of zero on one seed says little: five more rigs,
    // full-length S1 and S4 runs, 1 % missing samples.
    for (unsigned seed = 2; seed <= 6; ++seed) {
        rig::RigSpec spec;
        spec.runs = {rig::defaultMovingStates()[0], rig::defaultMovingStates()[3]};
        spec.seed = seed;
        spec.dropout_probability = 0.01;
        const Campaign campaign = rig::simulateCampaign(spec);
        for (const driftlab::Run& run : campaign.runs)
            for (const auto& [id, channel] :
                 checkRun(run.samples, campaign.channels, {}, kDefaults))
                EXPECT_TRUE(channel.summary.healthy())
                    << "seed " << seed << ": " << channel.summary.describe().toStdString();
    }
}

TEST(SensorHealth, cleanExampleBundleRaisesNoFlag) {
    const auto read = bundle::readBundle(
        QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/examples/x-axis-moving-state"));
    ASSERT_TRUE(read.campaign.has_value());
    std::size_t checkedRows = 0;
    for (const driftlab::Run& run : read.campaign->runs) {
        for (const auto& [id, channel] :
             checkRun(run.samples, read.campaign->channels, {}, kDefaults)) {
            SCOPED_TRACE((run.id + QLatin1Char('/') + id).toStdString());
            EXPECT_TRUE(channel.summary.healthy()) << channel.summary.describe().toStdString();
        }
        checkedRows += run.samples.rowCount();
    }
    EXPECT_GT(checkedRows, 500u);
}

// An open Pt100 reads the module's overflow (or > 850 °C), a short ≈ −242 °C.
class OpenOrShort : public ::testing::TestWithParam<double> {};

TEST_P(OpenOrShort, isOutOfRangeAtTheInjectedSamplesOnly) {
    SampleSeries series = cleanRun().samples;
    const QString id = QStringLiteral("T_bearing_fixed");
    const std::size_t first = rowAt(series, 1800);
    const std::size_t last = first + 11;  // two minutes
    for (std::size_t i = first; i <= last; ++i) columnOf(series, id)[i] = GetParam();

    const ChannelHealth health = checkTemperature(series, id);
    EXPECT_EQ(flaggedRows(health.flags), indexRange(first, last));
    EXPECT_EQ(rowsWith(health.flags, SensorFault::OutOfRange), indexRange(first, last));
    EXPECT_EQ(health.summary.channel, id);
    const FaultFinding& finding = onlyFinding(health.summary, SensorFault::OutOfRange);
    EXPECT_EQ(finding.samples, 12u);
    ASSERT_EQ(finding.ranges.size(), 1u);
    EXPECT_EQ(finding.ranges[0].from_s, series.time_s[first]);
    EXPECT_EQ(finding.ranges[0].to_s, series.time_s[last]);
    EXPECT_TRUE(health.summary.describe().contains(QStringLiteral("out_of_range")));
}

INSTANTIATE_TEST_SUITE_P(Pt100, OpenOrShort, ::testing::Values(32767.0, 850.5, -242.0));

TEST(SensorHealth, aValueHeldForTenMinutesIsFrozen) {
    SampleSeries series = cleanRun().samples;
    const QString id = QStringLiteral("T_nut");
    // During the warm-up the nut warms: the release after the hold jumps.
    const std::size_t first = rowAt(series, 1200);
    const std::size_t last = rowAt(series, 1800);
    auto& values = columnOf(series, id);
    for (std::size_t i = first + 1; i <= last; ++i) values[i] = values[first];
    ASSERT_GT(values[last + 1] - values[last], 0.02);

    const ChannelHealth health = checkTemperature(series, id);
    const auto frozen = rowsWith(health.flags, SensorFault::Frozen);
    for (std::size_t i = first; i <= last; ++i)
        EXPECT_TRUE(has(health.flags[i], SensorFault::Frozen)) << i;
    // The held value is a real reading: the sample before it may equal it
    // within a quantum, so the stretch may start up to two samples early.
    ASSERT_FALSE(frozen.empty());
    EXPECT_GE(frozen.front() + 2, first);
    EXPECT_EQ(frozen.back(), last);
    EXPECT_EQ(flaggedRows(health.flags), frozen) << health.summary.describe().toStdString();
    const FaultFinding& finding = onlyFinding(health.summary, SensorFault::Frozen);
    ASSERT_EQ(finding.ranges.size(), 1u);
    EXPECT_EQ(finding.ranges[0].from_s, series.time_s[frozen.front()]);
    EXPECT_EQ(finding.ranges[0].to_s, series.time_s[last]);
    EXPECT_EQ(finding.samples, frozen.size());
}

TEST(SensorHealth, theRecoveryAfterAFrozenStretchIsNotTakenForAStep) {
    // A bearing seat held for 10 min early in the warm-up: when the sensor
    // recovers, the reading jumps by more than a 10 s step may, but the rate
    // is judged against the sample before the stretch.
    SampleSeries series = cleanRun().samples;
    const QString id = QStringLiteral("T_bearing_fixed");
    const std::size_t first = rowAt(series, 300);
    const std::size_t last = rowAt(series, 900);
    auto& values = columnOf(series, id);
    for (std::size_t i = first + 1; i <= last; ++i) values[i] = values[first];
    const double allowedIn10s_K =
        kDefaults.max_rate_K_per_s * 10 + kDefaults.rate_noise_allowance_K;
    ASSERT_GT(values[last + 1] - values[last], allowedIn10s_K);

    const ChannelHealth health = checkTemperature(series, id);
    EXPECT_EQ(flaggedRows(health.flags), rowsWith(health.flags, SensorFault::Frozen))
        << health.summary.describe().toStdString();
    EXPECT_EQ(rowsWith(health.flags, SensorFault::Frozen).back(), last);
}

TEST(SensorHealth, isolatedEmiSpikesAreFlaggedAndTheirNeighboursAreNot) {
    SampleSeries series = cleanRun().samples;
    const QString id = QStringLiteral("T_ambient");
    // Two spikes in the warm-up (nut warming fast) and one in the cool-down.
    const std::vector<std::size_t> rows = {rowAt(series, 400), rowAt(series, 2500),
                                           rowAt(series, 4000)};
    const double kick_K[] = {5, -5, 5};
    for (std::size_t k = 0; k < rows.size(); ++k) columnOf(series, id)[rows[k]] += kick_K[k];

    const ChannelHealth health = checkTemperature(series, id);
    EXPECT_EQ(flaggedRows(health.flags), rows) << health.summary.describe().toStdString();
    EXPECT_EQ(rowsWith(health.flags, SensorFault::Spike), rows);
    const FaultFinding& finding = onlyFinding(health.summary, SensorFault::Spike);
    EXPECT_EQ(finding.samples, 3u);
    ASSERT_EQ(finding.ranges.size(), 3u);
    for (std::size_t k = 0; k < rows.size(); ++k)
        EXPECT_EQ(finding.ranges[k].from_s, series.time_s[rows[k]]);

    // A spike on a bearing while it warms: the trend is not a spike.
    SampleSeries bearing = cleanRun().samples;
    const QString bearingId = QStringLiteral("T_bearing_fixed");
    columnOf(bearing, bearingId)[rows[0]] -= 5;
    EXPECT_EQ(flaggedRows(checkTemperature(bearing, bearingId).flags),
              std::vector<std::size_t>{rows[0]});
}

TEST(SensorHealth, aStepFasterThanTheThermalMassAllowsIsFlaggedOnce) {
    SampleSeries series = cleanRun().samples;
    const QString id = QStringLiteral("T_bearing_free");
    const std::size_t step = rowAt(series, 2000);
    auto& values = columnOf(series, id);
    for (std::size_t i = step; i < values.size(); ++i) values[i] += 3;  // 3 K in 10 s

    const ChannelHealth health = checkTemperature(series, id);
    EXPECT_EQ(flaggedRows(health.flags), std::vector<std::size_t>{step})
        << health.summary.describe().toStdString();
    const FaultFinding& finding = onlyFinding(health.summary, SensorFault::RateOfChange);
    ASSERT_EQ(finding.ranges.size(), 1u);
    EXPECT_EQ(finding.ranges[0].from_s, series.time_s[step]);

    // 0.6 K in 10 s is within 0.05 K/s · 10 s + 0.2 K: not flagged.
    SampleSeries gentle = cleanRun().samples;
    auto& gentleValues = columnOf(gentle, id);
    for (std::size_t i = step; i < gentleValues.size(); ++i) gentleValues[i] += 0.6;
    EXPECT_TRUE(checkTemperature(gentle, id).summary.healthy());
}

namespace {

/// A second Pt100 beside T_air: the same air, its own calibration offset
/// (+0.3 K) and its own noise, quantised like the module.
SampleSeries withAirTwin(const SampleSeries& clean, double drift_K_per_s, double driftFrom_s) {
    SampleSeries series = clean;
    std::vector<double> twin = columnOf(clean, QStringLiteral("T_air"));
    std::mt19937_64 rng(7);
    std::normal_distribution<double> noise(0.0, 0.02);
    for (std::size_t i = 0; i < twin.size(); ++i) {
        const double drift = std::max(0.0, series.time_s[i] - driftFrom_s) * drift_K_per_s;
        twin[i] = std::round((twin[i] + 0.3 + noise(rng) + drift) * 100) / 100;
    }
    series.columns.push_back(QStringLiteral("T_air_twin"));
    series.values.push_back(twin);
    return series;
}

std::vector<Channel> channelsWithTwin() {
    std::vector<Channel> channels = cleanCampaign().channels;
    Channel twin = *cleanCampaign().findChannel(QStringLiteral("T_air"));
    twin.id = QStringLiteral("T_air_twin");
    channels.push_back(twin);
    return channels;
}

}  // namespace

TEST(SensorHealth, slowDriftOfOneOfTwoRedundantSensorsIsFlaggedOnBoth) {
    const std::vector<RedundantPair> pair = {
        {QStringLiteral("T_air"), QStringLiteral("T_air_twin")}};
    const SampleSeries clean = withAirTwin(cleanRun().samples, 0, 0);
    for (const auto& [id, health] : checkRun(clean, channelsWithTwin(), pair, kDefaults))
        EXPECT_TRUE(health.summary.healthy()) << health.summary.describe().toStdString();

    // 0.5 mK/s from 3000 s: 1.2 K at the end of the run, too slow for any
    // single-channel check.
    constexpr double kDrift_K_per_s = 0.0005;
    constexpr double kDriftFrom_s = 3000;
    const SampleSeries drifting = withAirTwin(cleanRun().samples, kDrift_K_per_s, kDriftFrom_s);
    const auto health = checkRun(drifting, channelsWithTwin(), pair, kDefaults);
    for (const QString& id : {QStringLiteral("T_air"), QStringLiteral("T_air_twin")}) {
        SCOPED_TRACE(id.toStdString());
        const ChannelHealth& channel = health.at(id);
        const auto rows = rowsWith(channel.flags, SensorFault::RedundantDrift);
        EXPECT_EQ(flaggedRows(channel.flags), rows);
        ASSERT_FALSE(rows.empty());
        // Flagged from some point on, to the end, and only where the injected
        // drift is near or beyond the 0.5 K limit (smoothing lags by ~2 min).
        EXPECT_EQ(rows, indexRange(rows.front(), drifting.rowCount() - 1));
        const double injectedAtFirstFlag_K =
            (drifting.time_s[rows.front()] - kDriftFrom_s) * kDrift_K_per_s;
        EXPECT_GT(injectedAtFirstFlag_K, 0.4);
        EXPECT_LT(injectedAtFirstFlag_K, 0.8);
        const FaultFinding& finding = onlyFinding(channel.summary, SensorFault::RedundantDrift);
        ASSERT_EQ(finding.ranges.size(), 1u);
        EXPECT_EQ(finding.ranges[0].to_s, drifting.time_s.back());
        EXPECT_EQ(channel.summary.channel, id);
    }
    // Channels outside the pair are untouched.
    EXPECT_TRUE(health.at(QStringLiteral("T_ambient")).summary.healthy());
}

TEST(SensorHealth, aPairNamingAChannelThatIsNotThereIsRefused) {
    const SampleSeries& series = cleanRun().samples;
    try {
        checkRun(series, cleanCampaign().channels,
                 {{QStringLiteral("T_air"), QStringLiteral("T_air_spare")}}, kDefaults);
        FAIL() << "accepted a pair with an unknown channel";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("T_air_spare"), std::string::npos) << e.what();
    }
}
