#pragma once
// Sensor self-diagnosis (docs/sensor-health.md): what can be wrong with a
// sensor's readings, one bit per kind, and the named thresholds of every check.
// A bad sample is flagged, never altered or dropped: what to do with it is the
// caller's decision (models, database and GUI are not part of this module).

#include <QString>
#include <QStringList>
#include <cstdint>

#include "core/domain/Channel.h"

namespace driftlab::sensors {

/// One kind of finding. A sample's flags are a bitmask of these.
enum class SensorFault : std::uint32_t {
    OutOfRange = 1u << 0,      ///< open or shorted element, overflow value of the module
    Frozen = 1u << 1,          ///< the value stopped moving while a live sensor always shows noise
    Spike = 1u << 2,           ///< isolated outlier (EMI), Hampel filter
    RateOfChange = 1u << 3,    ///< faster than the thermal mass allows
    RedundantDrift = 1u << 4,  ///< two sensors at the same place diverge
};
using SensorFlags = std::uint32_t;
inline constexpr SensorFlags kNoFlags = 0;

inline constexpr SensorFlags bit(SensorFault fault) {
    return static_cast<SensorFlags>(fault);
}
inline constexpr bool has(SensorFlags flags, SensorFault fault) {
    return (flags & bit(fault)) != 0;
}
/// All kinds, in bit order.
inline constexpr SensorFault kAllSensorFaults[] = {SensorFault::OutOfRange, SensorFault::Frozen,
                                                   SensorFault::Spike, SensorFault::RateOfChange,
                                                   SensorFault::RedundantDrift};

/// Stable id of a kind: "out_of_range", "frozen", "spike", "rate_of_change", "redundant_drift".
QString toString(SensorFault fault);
/// The ids of every kind set in `flags`.
QStringList toStringList(SensorFlags flags);

/// Thresholds of the checks. Defaults fit a test rig's temperature sensors: Pt100 or
/// thermocouple channels read by a module with 0.01 K resolution and about
/// 0.02 K noise, sampled every 1–10 s. docs/sensor-health.md says why.
struct SensorHealthSettings {
    // Out of range, per quantity. An open Pt100 reads above ~850 °C or the
    // module's overflow value, a short ≈ −242 °C: both far outside a lab.
    double temperature_min_C = -30;
    double temperature_max_C = 150;
    double displacement_max_abs_um = 5000;
    double speed_max_abs_rpm = 100'000;

    // Frozen value (temperature channels): the value stays within
    // frozen_tolerance_K (one quantisation step) for at least frozen_window_s
    // and at least frozen_min_samples samples.
    double frozen_window_s = 300;
    int frozen_min_samples = 20;
    double frozen_tolerance_K = 0.01;

    // Spikes (temperature channels): Hampel filter, |x − median| >
    // max(k · 1.4826 · MAD, spike_min_deviation_K) over a centred window of
    // 2·spike_half_window_samples + 1 samples. Live verdicts lag by the half window.
    int spike_half_window_samples = 5;
    double spike_mad_factor = 4;
    double spike_min_deviation_K = 0.3;

    // Rate of change (temperature channels): |Δvalue| > max_rate_K_per_s · Δt
    // + rate_noise_allowance_K between two accepted samples.
    double max_rate_K_per_s = 0.05;
    double rate_noise_allowance_K = 0.2;

    // Drift between redundant sensors: the difference of the pair minus its
    // mean over the first redundant_baseline_s, smoothed with a time constant
    // of redundant_smoothing_s, beyond redundant_drift_limit_K.
    double redundant_baseline_s = 600;
    double redundant_smoothing_s = 120;
    double redundant_drift_limit_K = 0.5;

    /// False, with a message naming the setting, for thresholds that cannot work.
    bool isValid(QString* error) const;
};

/// Whether `value` is outside the plausible range of `quantity` (NaN is not:
/// a missing sample is a dropout, not a reading).
bool outOfRange(const SensorHealthSettings& settings, Quantity quantity, double value);

}  // namespace driftlab::sensors
