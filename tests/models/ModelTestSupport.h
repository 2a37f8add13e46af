#pragma once
// Synthetic campaigns for the model tests: a feed axis (fixed end at −40 mm,
// lead 10 mm, travel 0–700 mm) with temperature channels and axis columns whose
// values come from functions of time, and interferometer passes whose thermal
// error is a known function of time and position.

#include <QString>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "core/domain/Campaign.h"

namespace driftlab::test {

/// A sampled quantity as a function of time since the run's start.
using Profile = std::function<double(double time_s)>;

constexpr double kFixedEndMm = -40;
constexpr double kLeadMm = 10;

/// 0 up to 60 s (so the rise reference is exact), then a first-order rise to 1
/// with time constant tau_s until warmupEnd_s, then a first-order decay.
double warmCool(double time_s, double tau_s, double warmupEnd_s);

/// Closed form of the first-order lag (τ2) of a first-order rise (τ1) started
/// at rest: y(s) = 1 − (τ1·e^(−s/τ1) − τ2·e^(−s/τ2))/(τ1 − τ2); 0 for s ≤ 0.
double lagOfRise(double s, double tau1_s, double tau2_s);

/// A random walk (steps of `step_K` per `dt_s`) around 20 °C, deterministic in `seed`.
Profile randomWalk(unsigned seed, double step_K, double dt_s, double duration_s);

/// A feed-axis campaign with these temperature channels and the position,
/// feed and torque columns.
Campaign feedAxisCampaign(const std::vector<std::pair<QString, ChannelRole>>& temperatures);

/// A moving run sampled every step_s from 0 to duration_s; a column without a
/// profile is missing (NaN) throughout.
Run sampledRun(const Campaign& campaign, const QString& id, double duration_s, double step_s,
               const std::map<QString, Profile>& columns);

/// The interferometer targets: 0, 100, …, 700 mm.
std::vector<double> targetsMm();

/// Bidirectional passes over targetsMm(): cycle 0 at t = 0 reads a cold
/// geometric error and backlash; cycle k at k·interval_s (up to until_s) reads
/// the same plus `thermalError_um(t, x)`.
void addPositioning(Run& run, double interval_s, double until_s,
                    const std::function<double(double time_s, double x_mm)>& thermalError_um);

/// The gains of E = ΔT_nut·(a1 + b1·(x − x_fixed)) + ΔT_bearing·(a2 + b2·(x − x_fixed)).
struct TwoSensorGains {
    double a1 = 0.8;     ///< µm/K
    double b1 = 0.0105;  ///< µm/(K·mm)
    double a2 = 1.5;     ///< µm/K
    double b2 = -0.002;  ///< µm/(K·mm)
};

/// A campaign with five temperature channels — T_nut (nut), T_bearing
/// (bearing) and three random-walk distractors T_air (air), T_bed (structure),
/// T_motor (motor) — and `runs` moving runs S1, S2, … (4 h, sampled every 10 s,
/// a pass every 600 s) whose heating differs from run to run and whose thermal
/// error is exactly the two-sensor model with `gains` scaled by
/// gainScale(run index).
Campaign twoSensorCampaign(int runs, const TwoSensorGains& gains,
                           const std::function<double(int run)>& gainScale = {});

}  // namespace driftlab::test
