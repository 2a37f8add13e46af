#include "core/sensors/SensorHealthSettings.h"

#include <cmath>

#include "core/bundle/ValueLimits.h"

namespace driftlab::sensors {
namespace {

bool refuse(QString* error, const QString& message) {
    if (error) *error = message;
    return false;
}

bool positiveFinite(double value) {
    return std::isfinite(value) && value > 0;
}

}  // namespace

QString toString(SensorFault fault) {
    switch (fault) {
        case SensorFault::OutOfRange:
            return QStringLiteral("out_of_range");
        case SensorFault::Frozen:
            return QStringLiteral("frozen");
        case SensorFault::Spike:
            return QStringLiteral("spike");
        case SensorFault::RateOfChange:
            return QStringLiteral("rate_of_change");
        case SensorFault::RedundantDrift:
            return QStringLiteral("redundant_drift");
    }
    return QStringLiteral("unknown");
}

QStringList toStringList(SensorFlags flags) {
    QStringList names;
    for (SensorFault fault : kAllSensorFaults)
        if (has(flags, fault)) names << toString(fault);
    return names;
}

bool SensorHealthSettings::isValid(QString* error) const {
    if (!std::isfinite(temperature_min_C) || !std::isfinite(temperature_max_C) ||
        temperature_min_C >= temperature_max_C)
        return refuse(error, QStringLiteral("temperature_min_C must be below temperature_max_C"));
    // A short of a Pt100 reads about −242 °C: a lower limit below that would
    // accept a shorted element as a reading.
    if (temperature_min_C <= -242)
        return refuse(error, QStringLiteral("temperature_min_C must be above −242 °C, the "
                                            "reading of a shorted Pt100"));
    if (!positiveFinite(displacement_max_abs_um))
        return refuse(error, QStringLiteral("displacement_max_abs_um must be > 0"));
    if (!positiveFinite(speed_max_abs_rpm))
        return refuse(error, QStringLiteral("speed_max_abs_rpm must be > 0"));
    if (!positiveFinite(frozen_window_s))
        return refuse(error, QStringLiteral("frozen_window_s must be > 0"));
    if (frozen_min_samples < 2)
        return refuse(error, QStringLiteral("frozen_min_samples must be at least 2"));
    // Zero tolerance would call a live sensor that repeats a code "moving";
    // a tolerance of a kelvin would call a quiet, live room sensor frozen.
    if (!std::isfinite(frozen_tolerance_K) || frozen_tolerance_K < 0 || frozen_tolerance_K > 0.5)
        return refuse(error, QStringLiteral("frozen_tolerance_K must be within 0…0.5 K"));
    // Without a neighbour on each side there is no median to compare with;
    // above 500 samples the live verdicts lag by too much.
    if (spike_half_window_samples < 1 || spike_half_window_samples > 500)
        return refuse(error, QStringLiteral("spike_half_window_samples must be within 1…500"));
    if (!positiveFinite(spike_mad_factor))
        return refuse(error, QStringLiteral("spike_mad_factor must be > 0"));
    // MAD is 0 on quantised data that repeats a code: without a floor every
    // noise step would be a spike.
    if (!positiveFinite(spike_min_deviation_K))
        return refuse(error, QStringLiteral("spike_min_deviation_K must be > 0 (MAD is 0 on "
                                            "quantised data)"));
    if (!positiveFinite(max_rate_K_per_s))
        return refuse(error, QStringLiteral("max_rate_K_per_s must be > 0"));
    if (!std::isfinite(rate_noise_allowance_K) || rate_noise_allowance_K < 0)
        return refuse(error, QStringLiteral("rate_noise_allowance_K must be >= 0"));
    if (!positiveFinite(redundant_baseline_s))
        return refuse(error, QStringLiteral("redundant_baseline_s must be > 0"));
    if (!std::isfinite(redundant_smoothing_s) || redundant_smoothing_s < 0)
        return refuse(error, QStringLiteral("redundant_smoothing_s must be >= 0"));
    if (!positiveFinite(redundant_drift_limit_K))
        return refuse(error, QStringLiteral("redundant_drift_limit_K must be > 0"));
    return true;
}

bool outOfRange(const SensorHealthSettings& settings, Quantity quantity, double value) {
    if (std::isnan(value)) return false;
    if (!std::isfinite(value)) return true;
    // What the bundle reader calls impossible is never a plausible reading;
    // the settings narrow that to the lab.
    if (bundle::impossibleValue(quantity, value)) return true;
    switch (quantity) {
        case Quantity::Temperature:
            return value < settings.temperature_min_C || value > settings.temperature_max_C;
        case Quantity::Displacement:
            return std::abs(value) > settings.displacement_max_abs_um;
        case Quantity::Speed:
            return std::abs(value) > settings.speed_max_abs_rpm;
    }
    return false;
}

}  // namespace driftlab::sensors
