// The lag models: the exact first-order response and the exponential model's
// time constants on a two-source warm-up/cool-down.

#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

#include "core/models/ExponentialModel.h"
#include "core/models/FirstOrderLag.h"
#include "tests/models/ModelTestSupport.h"

namespace driftlab::models {
namespace {

/// rad/s of the screw at a feed, for the test campaign's 10 mm lead.
double screwSpeed(double feed_mm_min) {
    return 2 * std::numbers::pi * std::abs(feed_mm_min) / (60 * test::kLeadMm);
}

/// Closed-form response of a unit-gain first-order lag at rest to an input
/// that steps to levels[i].second at levels[i].first.
double lagOfSteps(const std::vector<std::pair<double, double>>& levels, double tau, double t) {
    double e = 0, from = 0, u = 0;
    for (const auto& [at, level] : levels) {
        if (at > t) break;
        e = u + (e - u) * std::exp(-(at - from) / tau);
        from = at;
        u = level;
    }
    return u + (e - u) * std::exp(-(t - from) / tau);
}

std::vector<RunData> dataset(const Campaign& c) {
    const DatasetResult data = buildDataset(c, {QStringLiteral("S1")});
    EXPECT_TRUE(data.ok()) << qPrintable(data.error);
    return data.runs;
}

void expectParameter(const FitSummary& fit, const QString& name, double expected, double relative) {
    ASSERT_TRUE(fit.parameters.count(name)) << qPrintable(name);
    EXPECT_NEAR(fit.parameters.at(name).value, expected, relative * std::abs(expected))
        << qPrintable(name);
}

TEST(FirstOrderLag, matchesTheClosedFormAtUnsortedTimes) {
    const PiecewiseInput input{{100, 700}, {2, 0}};
    const std::vector<double> at{1000, 50, 400, 100, 700};
    const Eigen::VectorXd e = lagResponse(input, 300, at);
    const std::vector<std::pair<double, double>> levels{{100, 2}, {700, 0}};
    for (std::size_t i = 0; i < at.size(); ++i)
        EXPECT_NEAR(e[Eigen::Index(i)], lagOfSteps(levels, 300, at[i]), 1e-12) << at[i];
}

TEST(FirstOrderLag, matchesTheClosedFormWhereTheLoggingIntervalChanges) {
    // A logger at 10 s, one late sample, then 10 s again and a burst at 2.5 s:
    // the decay factor of a repeated interval is reused, a new one recomputed.
    PiecewiseInput input;
    std::vector<std::pair<double, double>> levels;
    for (double t : {0.0, 10.0, 20.0, 30.0, 43.7, 53.7, 63.7, 66.2, 68.7, 71.2, 81.2}) {
        const double u = std::sin(t / 9) + 1.5;
        input.time_s.push_back(t);
        input.value.push_back(u);
        levels.emplace_back(t, u);
    }
    const std::vector<double> at{0, 5, 10, 30, 40, 43.7, 60, 66.2, 70, 81.2, 150};
    const Eigen::VectorXd e = lagResponse(input, 45, at);
    for (std::size_t i = 0; i < at.size(); ++i)
        EXPECT_NEAR(e[Eigen::Index(i)], lagOfSteps(levels, 45, at[i]), 1e-12) << at[i];
}

TEST(ExponentialModel, recoversTheTimeConstantsOfTwoSources) {
    const double warmup_s = 3 * 3600, duration_s = 5 * 3600, feed = 8000;
    const double tau1 = 900, a1 = 0.01, b1 = 1.2e-4;
    const double tau2 = 4000, a2 = 0.03, b2 = -2e-5;
    Campaign c = test::feedAxisCampaign({});
    driftlab::Run run = test::sampledRun(c, QStringLiteral("S1"), duration_s, 60, {});
    // Reciprocating strokes over 210-490 mm during the warm-up, then rest.
    for (int k = 0; k * 2.1 < warmup_s; ++k) {
        const double t = k * 2.1;
        const bool out = k % 2 == 0;
        run.motion.push_back({t, std::min(t + 2.1, warmup_s), out ? 210.0 : 490.0,
                              out ? 490.0 : 210.0, out ? feed : -feed});
    }
    const std::vector<std::pair<double, double>> activity{{0, screwSpeed(feed)}, {warmup_s, 0}};
    test::addPositioning(run, 300, duration_s, [&](double t, double x) {
        const double dx = x - test::kFixedEndMm;
        return lagOfSteps(activity, tau1, t) * (a1 + b1 * dx) +
               lagOfSteps(activity, tau2, t) * (a2 + b2 * dx);
    });
    c.runs.push_back(run);

    ExponentialModel model;
    const FitSummary fit = model.fit(dataset(c));
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    expectParameter(fit, QStringLiteral("source1.tau"), tau1, 0.01);
    expectParameter(fit, QStringLiteral("source2.tau"), tau2, 0.01);
    expectParameter(fit, QStringLiteral("source1.a"), a1, 0.01);
    expectParameter(fit, QStringLiteral("source1.b"), b1, 0.01);
    expectParameter(fit, QStringLiteral("source2.a"), a2, 0.01);
    expectParameter(fit, QStringLiteral("source2.b"), b2, 0.01);
    EXPECT_EQ(fit.parameters.at(QStringLiteral("source1.a")).unit, QStringLiteral("µm/(rad/s)"));
    EXPECT_GT(fit.iterations, 0);
    EXPECT_LT(fit.rms_um, 1e-3);
    EXPECT_EQ(fit.inputs, QStringList({QStringLiteral("motion")}));
    EXPECT_TRUE(std::isfinite(fit.parameters.at(QStringLiteral("source2.tau")).sigma));
}

TEST(ExponentialModel, needsTheScrewSpeed) {
    Campaign c = test::feedAxisCampaign({});
    driftlab::Run run = test::sampledRun(c, QStringLiteral("S1"), 3600, 60, {});
    test::addPositioning(run, 600, 3600, [](double t, double) { return t / 3600; });
    c.runs.push_back(run);
    ExponentialModel model;
    const FitSummary fit = model.fit(dataset(c));
    EXPECT_FALSE(fit.success);
    EXPECT_EQ(fit.message, QStringLiteral("model 'exponential' needs the screw speed: run 'S1' has "
                                          "no samples in column 'feed_mm_min'"));
}

}  // namespace
}  // namespace driftlab::models
