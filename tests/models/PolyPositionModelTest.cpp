// The polynomial-in-temperature × position model: exact recovery of known
// coefficients, the degree chosen by cross-validation, the bearing nearest the
// fixed end, and the roles it needs.

#include <gtest/gtest.h>
#include <cmath>

#include "core/models/PolyPositionModel.h"
#include "tests/models/ModelTestSupport.h"

namespace driftlab::models {
namespace {

struct PolyTruth {
    double a1 = 0.012, a2 = -0.0009, b = 0.004, c = 0.0002;
};

/// Two runs with a quadratic nut term and two bearings, of which only the one
/// at the fixed end enters the error.
Campaign quadraticCampaign(const PolyTruth& k) {
    Campaign c =
        test::feedAxisCampaign({{QStringLiteral("T_nut"), ChannelRole::Nut},
                                {QStringLiteral("T_bearing_free"), ChannelRole::Bearing},
                                {QStringLiteral("T_bearing_fixed"), ChannelRole::Bearing}});
    c.channels[1].position_mm = 857.5;
    c.channels[2].position_mm = -37.5;
    for (int r = 0; r < 2; ++r) {
        auto nut = [=](double t) {
            return (6.0 + 2 * r) * test::warmCool(t, 1000 + 400 * r, 9000);
        };
        auto fixed = [=](double t) { return (2.0 + r) * test::warmCool(t, 3500, 9000); };
        auto free = [=](double t) { return 1.5 * test::warmCool(t, 2500 - 500 * r, 9000); };
        driftlab::Run run = test::sampledRun(
            c, QStringLiteral("S%1").arg(r + 1), 4 * 3600, 10,
            {{QStringLiteral("T_nut"), [=](double t) { return 20 + nut(t); }},
             {QStringLiteral("T_bearing_free"), [=](double t) { return 20 + free(t); }},
             {QStringLiteral("T_bearing_fixed"), [=](double t) { return 20 + fixed(t); }}});
        test::addPositioning(run, 600, 4 * 3600, [=](double t, double x) {
            const double n = nut(t);
            return (k.a1 * n + k.a2 * n * n + k.b * fixed(t) + k.c) * (x - test::kFixedEndMm);
        });
        c.runs.push_back(run);
    }
    return c;
}

TEST(PolyPositionModel, recoversKnownCoefficientsAndChoosesTheDegree) {
    const PolyTruth k;
    const DatasetResult data =
        buildDataset(quadraticCampaign(k), {QStringLiteral("S1"), QStringLiteral("S2")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    PolyPositionModel model;
    const FitSummary fit = model.fit(data.runs);
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_EQ(fit.metrics.at(QStringLiteral("degree")), 2);
    EXPECT_EQ(fit.inputs,
              QStringList({QStringLiteral("T_nut"), QStringLiteral("T_bearing_fixed")}));
    const std::pair<const char*, double> expected[] = {
        {"a1", k.a1}, {"a2", k.a2}, {"b", k.b}, {"c", k.c}};
    for (const auto& [name, value] : expected) {
        const Parameter& p = fit.parameters.at(QString::fromLatin1(name));
        EXPECT_NEAR(p.value, value, 1e-8 * std::abs(value)) << name;
    }
    EXPECT_EQ(fit.parameters.size(), 4u);
    EXPECT_EQ(fit.parameters.at(QStringLiteral("a2")).unit, QStringLiteral("µm/(mm·K²)"));
    EXPECT_LT(fit.rms_um, 1e-9);
}

TEST(PolyPositionModel, linearDataGetDegreeOne) {
    const PolyTruth k{0.01, 0, 0.003, 0};
    const DatasetResult data =
        buildDataset(quadraticCampaign(k), {QStringLiteral("S1"), QStringLiteral("S2")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    PolyPositionModel model;
    const FitSummary fit = model.fit(data.runs);
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_EQ(fit.metrics.at(QStringLiteral("degree")), 1);
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("a1")).value, 0.01, 1e-10);
}

TEST(PolyPositionModel, needsANutChannel) {
    Campaign c = quadraticCampaign({});
    c.channels[0].role = ChannelRole::Other;
    const DatasetResult data = buildDataset(c, {QStringLiteral("S1")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    PolyPositionModel model;
    const FitSummary fit = model.fit(data.runs);
    EXPECT_FALSE(fit.success);
    EXPECT_FALSE(model.isFitted());
    EXPECT_EQ(fit.message, QStringLiteral("model 'poly-position' needs a temperature channel with "
                                          "role 'nut'; this campaign has none"));
}

TEST(PolyPositionModel, holeInTheNutChannelLeavesOutItsPassAndTheFitStaysExact) {
    const PolyTruth k{};
    Campaign c = quadraticCampaign(k);
    std::vector<double>& nut = c.runs[1].samples.values[0];
    for (std::size_t i = 170; i < 190; ++i) nut[i] = std::nan("");
    const DatasetResult data = buildDataset(c, {QStringLiteral("S1"), QStringLiteral("S2")});
    ASSERT_TRUE(data.ok()) << qPrintable(data.error);
    // The nut warms steeply there (a noiseless channel allows no bridge):
    // the pass at 1800 s is left out, and the exact model is found on the rest.
    ASSERT_EQ(data.runs[1].gaps.size(), 1u);
    EXPECT_FALSE(data.runs[1].gaps.front().bridged);
    EXPECT_EQ(data.runs[1].gaps.front().observations_left_out, 16u);
    PolyPositionModel model;
    const FitSummary fit = model.fit(data.runs);
    ASSERT_TRUE(fit.success) << qPrintable(fit.message);
    EXPECT_LT(fit.rms_um, 1e-6);
}

}  // namespace
}  // namespace driftlab::models
