// Effects, module outages, sensors and the spindle test of the simulated rig.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/rig/ModuleOutage.h"
#include "core/rig/RigEffects.h"
#include "core/rig/SensorModel.h"
#include "core/rig/SpindleTestSimulator.h"

using namespace driftlab;
using namespace driftlab::rig;

TEST(RigEffects, everyCauseIdOfTheDiagnosisCanBeSwitchedOnWithAMagnitude) {
    RigEffects e;
    QString error;
    for (const char* assignment :
         {"forced_convection=0.1", "nut_heat_exponent=1.5", "motor_heat=0.2",
          "sensor_lag:T_nut=300", "sensor_offset:T_bearing_fixed=-0.4", "air_refraction=1",
          "frame_growth=2.5"})
        EXPECT_TRUE(applyEffect(e, QString::fromLatin1(assignment), &error)) << qPrintable(error);
    EXPECT_DOUBLE_EQ(e.forced_convection_h1, 0.1);
    EXPECT_DOUBLE_EQ(e.nut_heat_exponent, 1.5);
    EXPECT_DOUBLE_EQ(e.motor_heat_W_per_Nm2, 0.2);
    EXPECT_DOUBLE_EQ(e.sensor_lag_s.at(QStringLiteral("T_nut")), 300);
    EXPECT_DOUBLE_EQ(e.sensor_offset_K.at(QStringLiteral("T_bearing_fixed")), -0.4);
    EXPECT_DOUBLE_EQ(e.air_refraction, 1);
    EXPECT_DOUBLE_EQ(e.frame_growth_um_per_K, 2.5);
    EXPECT_TRUE(e.any());
    EXPECT_FALSE(RigEffects{}.any());
}

TEST(RigEffects, badAssignmentsAreRefusedWithTheReason) {
    RigEffects e;
    QString error;
    EXPECT_FALSE(applyEffect(e, QStringLiteral("spindle_growth=1"), &error));
    EXPECT_TRUE(error.contains(
        QStringLiteral("unknown effect id 'spindle_growth' (known: forced_convection")))
        << qPrintable(error);
    EXPECT_FALSE(applyEffect(e, QStringLiteral("sensor_lag=30"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("needs a channel"))) << qPrintable(error);
    EXPECT_FALSE(applyEffect(e, QStringLiteral("forced_convection"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("expected ID=VALUE"))) << qPrintable(error);
    EXPECT_FALSE(applyEffect(e, QStringLiteral("motor_heat=lots"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("not a number"))) << qPrintable(error);
    EXPECT_FALSE(applyEffect(e, QStringLiteral("forced_convection=-1"), &error));
    EXPECT_FALSE(applyEffect(e, QStringLiteral("frame_growth:T_bed=1"), &error));
    EXPECT_FALSE(e.any());
}

TEST(ModuleOutage, runAtFromToInSecondsOfRunTime) {
    QString error;
    const auto outage = parseModuleOutage(QStringLiteral("S3@3000-3300"), &error);
    ASSERT_TRUE(outage) << qPrintable(error);
    EXPECT_EQ(*outage, (ModuleOutage{QStringLiteral("S3"), 3000, 3300}));
    const auto fractional = parseModuleOutage(QStringLiteral(" SP1@0-12.5 "), &error);
    ASSERT_TRUE(fractional) << qPrintable(error);
    EXPECT_EQ(*fractional, (ModuleOutage{QStringLiteral("SP1"), 0, 12.5}));
    for (const char* bad : {"S3", "S3@3000", "S3@3000-", "@3000-3300", "S3@-10-20", "S3@a-b",
                            "S3@3000-3300-3400", "S-3@1-2"}) {
        EXPECT_FALSE(parseModuleOutage(QString::fromLatin1(bad), &error)) << bad;
        EXPECT_TRUE(error.contains(QStringLiteral("'%1' is not RUN@FROM-TO").arg(bad)))
            << qPrintable(error);
    }
    EXPECT_FALSE(parseModuleOutage(QStringLiteral("S3@3300-3000"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("must end after it starts (FROM 3300 s, TO 3000 s)")))
        << qPrintable(error);
    EXPECT_FALSE(parseModuleOutage(QStringLiteral("S3@3000-3000"), &error));
}

TEST(ModuleOutage, aRunsOutagesAreSortedAndMergedAndEndBeforeTheirTo) {
    const std::vector<ModuleOutage> all{{QStringLiteral("S2"), 500, 600},
                                        {QStringLiteral("S1"), 300, 400},
                                        {QStringLiteral("S2"), 100, 200},
                                        {QStringLiteral("S2"), 150, 250}};
    const auto s2 = outagesOf(all, QStringLiteral("S2"));
    ASSERT_EQ(s2.size(), 2u);
    EXPECT_EQ(s2[0], (ModuleOutage{QStringLiteral("S2"), 100, 250}));
    EXPECT_EQ(s2[1], (ModuleOutage{QStringLiteral("S2"), 500, 600}));
    EXPECT_TRUE(outagesOf(all, QStringLiteral("S3")).empty());
    EXPECT_TRUE(moduleAnswers(s2, 99.9));
    EXPECT_FALSE(moduleAnswers(s2, 100));
    EXPECT_FALSE(moduleAnswers(s2, 249.9));
    EXPECT_TRUE(moduleAnswers(s2, 250));
    EXPECT_TRUE(moduleAnswers({}, 100));
}

TEST(SensorModel, aLaggedSensorReaches63PercentOfAStepAfterOneTimeConstant) {
    SensorModel sensor({/*lag_s=*/100, 0, /*noise_K=*/0, /*quantum_K=*/0, 0}, 1);
    sensor.read(20, 1);
    double reading = 0;
    for (int i = 0; i < 100; ++i) reading = sensor.read(30, 1);
    EXPECT_NEAR(reading, 20 + 10 * (1 - std::exp(-1.0)), 1e-9);
}

TEST(SensorModel, offsetNoiseQuantisationAndDropouts) {
    SensorModel sensor({0, 0.5, 0.02, 0.01, 0.1}, 7);
    int dropouts = 0;
    std::vector<double> readings;
    for (int i = 0; i < 20000; ++i) {
        const double r = sensor.read(20.0, 1);
        if (std::isnan(r)) {
            ++dropouts;
            continue;
        }
        readings.push_back(r);
        EXPECT_NEAR(r * 100, std::round(r * 100), 1e-9) << "quantised to 0.01 K";
    }
    EXPECT_NEAR(dropouts / 20000.0, 0.1, 0.01);
    double mean = 0;
    for (double r : readings) mean += r / double(readings.size());
    EXPECT_NEAR(mean, 20.5, 0.002);
    double var = 0;
    for (double r : readings) var += (r - mean) * (r - mean) / double(readings.size());
    EXPECT_NEAR(std::sqrt(var), 0.02, 0.003);
}

TEST(SpindleTest, axialDriftGrowsWithSpeedAndRelaxesAtTheStops) {
    std::vector<QString> columns;
    for (const Channel& c : spindleTestChannels()) columns.push_back(c.id);
    columns.push_back(QStringLiteral("T_ambient"));
    const driftlab::Run run = simulateSpindleTest({}, columns);
    EXPECT_EQ(run.kind, RunKind::Spindle);
    const auto& z = run.samples.values[std::size_t(run.samples.columnIndex(QStringLiteral("D_z")))];
    const auto& t = run.samples.time_s;
    auto at = [&](double time_s) {
        return z[std::size_t(std::lower_bound(t.begin(), t.end(), time_s) - t.begin())];
    };
    EXPECT_NEAR(at(0), 0, 0.5);
    EXPECT_LT(at(3600), at(1800)) << "6000 rpm drifts further than 3000 rpm (z drift is negative)";
    EXPECT_GT(at(4500), at(3600)) << "the stop lets it relax";
    const double worst = *std::min_element(z.begin(), z.end());
    EXPECT_LT(worst, -15) << "tens of µm of axial drift at 9000 rpm";
    EXPECT_GT(worst, -80);
    // The shaft's share relaxes within the hour after the last stop; the column
    // core (τ of hours) keeps the rest.
    EXPECT_GT(at(t.back()), 0.7 * worst) << "an hour after the last stop a third is gone";
}
