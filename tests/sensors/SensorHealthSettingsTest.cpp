// Thresholds that cannot work are refused with a message naming the setting.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "core/sensors/ChannelHealthChecker.h"
#include "core/sensors/SensorHealth.h"

using namespace driftlab;
using namespace driftlab::sensors;

TEST(SensorHealthSettings, defaultsAreValid) {
    QString error;
    EXPECT_TRUE(SensorHealthSettings{}.isValid(&error)) << error.toStdString();
}

TEST(SensorHealthSettings, settingsThatCannotWorkAreRefusedByName) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    struct Case {
        const char* setting;
        std::function<void(SensorHealthSettings&)> spoil;
    };
    const std::vector<Case> cases = {
        {"temperature_min_C", [](auto& s) { s.temperature_min_C = 200; }},
        // Below −242 °C a shorted Pt100 would pass as a reading.
        {"temperature_min_C", [](auto& s) { s.temperature_min_C = -250; }},
        {"displacement_max_abs_um", [](auto& s) { s.displacement_max_abs_um = 0; }},
        {"speed_max_abs_rpm", [nan](auto& s) { s.speed_max_abs_rpm = nan; }},
        {"frozen_window_s", [](auto& s) { s.frozen_window_s = 0; }},
        {"frozen_tolerance_K", [](auto& s) { s.frozen_tolerance_K = 2; }},
        {"spike_half_window_samples", [](auto& s) { s.spike_half_window_samples = 0; }},
        {"spike_mad_factor", [](auto& s) { s.spike_mad_factor = -1; }},
        {"spike_min_deviation_K", [](auto& s) { s.spike_min_deviation_K = 0; }},
        {"max_rate_K_per_s", [](auto& s) { s.max_rate_K_per_s = 0; }},
        {"rate_noise_allowance_K", [](auto& s) { s.rate_noise_allowance_K = -0.1; }},
        {"redundant_baseline_s", [](auto& s) { s.redundant_baseline_s = 0; }},
        {"redundant_smoothing_s", [nan](auto& s) { s.redundant_smoothing_s = nan; }},
        {"redundant_drift_limit_K", [](auto& s) { s.redundant_drift_limit_K = 0; }},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.setting);
        SensorHealthSettings settings;
        c.spoil(settings);
        QString error;
        EXPECT_FALSE(settings.isValid(&error));
        EXPECT_TRUE(error.contains(QLatin1String(c.setting))) << error.toStdString();
        // The checkers refuse them too, with the same message.
        try {
            ChannelHealthChecker checker(QStringLiteral("T_nut"), Quantity::Temperature,
                                         applicableChecks(Quantity::Temperature, ChannelRole::Nut),
                                         settings);
            ADD_FAILURE() << "checker accepted invalid settings";
        } catch (const std::invalid_argument& e) {
            EXPECT_EQ(QString::fromStdString(e.what()), error);
        }
        EXPECT_THROW(RedundantPairChecker{settings}, std::invalid_argument);
    }
}
