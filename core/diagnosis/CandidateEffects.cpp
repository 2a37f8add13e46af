#include "core/diagnosis/CandidateEffects.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/diagnosis/LateSensor.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::diagnosis {
namespace {

using models::FreeParameter;
using models::PredictionPoint;
using models::ScrewRunInputs;
using models::ScrewRunOutputs;
using models::Signal;

constexpr double kReferenceSpeed_rad_s = physics::ScrewThermalParameters::kReferenceSpeed_rad_s;

/// Index of a sensor series by channel, or -1.
int sensorIndex(const ScrewRunInputs& in, const QString& channel) {
    for (std::size_t s = 0; s < in.sensors.size(); ++s)
        if (in.sensors[s].channel_id == channel) return int(s);
    return -1;
}

/// What a first-order element with time constant `tau_s` makes of `values`
/// sampled at `time_s`, exactly between samples for a signal held linear.
void firstOrderLag(const std::vector<double>& time_s, std::vector<double>& values, double tau_s) {
    if (!(tau_s > 0)) return;
    for (std::size_t k = 1; k < values.size(); ++k)
        values[k] += (values[k - 1] - values[k]) * std::exp(-(time_s[k] - time_s[k - 1]) / tau_s);
}

Signal lagged(Signal s, double tau_s) {
    firstOrderLag(s.time_s, s.value, tau_s);
    return s;
}

/// The interferometer reading moves by perKelvin·pathFactor(x)·rise(t).
void addToErrors(ScrewRunOutputs& out, const std::vector<PredictionPoint>& at, const Signal& rise,
                 const ScrewRunInputs& in, double perKelvin_um,
                 const std::function<double(double x_mm)>& pathFactor) {
    if (rise.empty()) return;
    for (std::size_t j = 0; j < at.size(); ++j)
        out.error_um[j] += perKelvin_um * pathFactor(at[j].position_mm) *
                           models::valueAt(rise, at[j].time_s, in.run_id);
}

/// Starting value of a lag: of a few time constants from none to four hours,
/// the one whose lagged structure rise best explains (least squares, one gain)
/// what the base model leaves on the training runs. The Ceres fit then refines
/// it; started far off, it would see no slope (a lag of seconds changes
/// nothing) or stall in the wrong valley.
double structureLagStart_s(const std::vector<models::RunData>& runs,
                           const std::vector<models::ReadingResiduals>& residuals) {
    double best = 600, bestLeft = std::numeric_limits<double>::infinity();
    for (const double tau : {0.0, 600.0, 1800.0, 3600.0, 7200.0, 14400.0}) {
        double xy = 0, xx = 0, yy = 0;
        for (std::size_t k = 0; k < runs.size() && k < residuals.size(); ++k) {
            const auto* structure = models::firstUsableOfRole(runs[k], ChannelRole::Structure);
            if (!structure) continue;
            const Signal rise = lagged(structure->rise_K, tau);
            const auto& r = residuals[k];
            for (std::size_t j = 0; j < r.points.size(); ++j) {
                const double x = models::valueAt(rise, r.points[j].time_s, runs[k].run_id);
                xy += x * r.error_um[j];
                xx += x * x;
                yy += r.error_um[j] * r.error_um[j];
            }
        }
        const double left = xx > 0 ? yy - xy * xy / xx : yy;
        if (left < bestLeft) bestLeft = left, best = std::max(tau, 1.0);
    }
    return best;
}

/// The room a late room sensor saw, on the simulation's even grid. The screw
/// soaked in the room so seen.
void roomBeforeItsSensor(double tau_s, ScrewRunInputs& in) {
    std::vector<double> time_s(in.ambient_C.size());
    for (std::size_t k = 0; k < time_s.size(); ++k) time_s[k] = double(k) * in.dt_s;
    in.ambient_C = beforeTheLag(time_s, in.ambient_C, tau_s);
    if (!in.ambient_C.empty()) in.initial_C = in.ambient_C.front();
}

/// The rise a late air or structure sensor saw, still a rise from the start.
void riseBeforeItsSensor(Signal& rise, double tau_s) {
    rise.value = beforeTheLag(rise.time_s, rise.value, tau_s);
    if (rise.value.empty()) return;
    const double start = rise.value.front();
    for (double& v : rise.value) v -= start;
}

/// A lag on a sensor off the screw: undone on the simulation's input, gain on
/// positioning (channel empty). `onTopOf`: the effect that reads the sensor.
CandidateEffect lateOffScrew(const QString& channel, const QString& measures,
                             const QString& onTopOf,
                             std::function<void(double tau_s, ScrewRunInputs&)> undo) {
    // A late air or structure sensor changes only what refraction and frame
    // growth read; a late room sensor changes the room the screw sees.
    return {.cause = QStringLiteral("sensor_lag:") + channel,
            .parameters = {{QStringLiteral("tau"), QStringLiteral("s"), 600, 1, 7200}},
            .inputs = [undo](const double* v, ScrewRunInputs& in) { undo(v[0], in); },
            .measures = measures,
            .on_top_of = onTopOf,
            .output_only = !onTopOf.isEmpty()};
}

CandidateEffect physical(const QString& cause, std::vector<FreeParameter> parameters,
                         std::function<void(const double*, physics::ScrewThermalParameters&)> f) {
    return {.cause = cause, .parameters = std::move(parameters), .physics = std::move(f)};
}

CandidateEffect onSensor(
    const QString& kind, const QString& channel, FreeParameter parameter,
    std::function<void(double, const ScrewRunInputs&, std::vector<double>&, std::size_t sensor)>
        apply) {
    return {.cause = kind + QLatin1Char(':') + channel,
            .channel = channel,
            .parameters = {std::move(parameter)},
            .readings =
                [channel, apply](const double* own, const ScrewRunInputs& in, const auto&,
                                 ScrewRunOutputs& out) {
                    const int s = sensorIndex(in, channel);
                    if (s >= 0) apply(own[0], in, out.sensor_C[std::size_t(s)], std::size_t(s));
                },
            .output_only = true};
}

/// Whether the runs move at more than one speed (top feeds 10 % apart or
/// more): only then can a speed exponent be told from a gain.
bool severalSpeeds(const std::vector<models::RunData>& runs) {
    std::vector<double> top;
    for (const auto& r : runs) {
        double feed = 0;
        for (const auto& m : r.motion) feed = std::max(feed, std::abs(m.feed_mm_min));
        for (double f : r.feed_mm_min.value) feed = std::max(feed, std::abs(f));
        if (feed > 0) top.push_back(feed);
    }
    for (double a : top)
        for (double b : top)
            if (std::abs(a - b) > 0.1 * std::max(a, b)) return true;
    return false;
}

bool allRunsHave(const std::vector<models::RunData>& runs, ChannelRole role) {
    for (const auto& r : runs)
        if (!models::firstUsableOfRole(r, role)) return false;
    return !runs.empty();
}

}  // namespace

std::vector<CandidateEffect> candidateEffects(
    const std::vector<models::RunData>& runs,
    const std::vector<models::ReadingResiduals>& baseResiduals) {
    std::vector<CandidateEffect> candidates;
    // h = h0 + Δh·(|ω|/ω_ref)^m: the rise Δh at 800 rpm keeps the two free
    // values apart (h1 per (rad/s)^m would change scale with m). Trained at
    // one speed, m cannot be told from Δh: it stays 1.
    std::vector<FreeParameter> convection{
        {QStringLiteral("dh_800rpm"), QStringLiteral("W/(m²·K)"), 1, 0, 200}};
    if (severalSpeeds(runs)) convection.push_back({QStringLiteral("m"), QString(), 1, 0.3, 3});
    const bool exponent = convection.size() > 1;
    candidates.push_back(physical(QStringLiteral("forced_convection"), convection,
                                  [exponent](const double* v, physics::ScrewThermalParameters& s) {
                                      s.forced_exponent = exponent ? v[1] : 1.0;
                                      s.h1_forced_W_m2K =
                                          v[0] / std::pow(kReferenceSpeed_rad_s, s.forced_exponent);
                                  }));
    candidates.push_back(physical(
        QStringLiteral("nut_heat_exponent"), {{QStringLiteral("n"), QString(), 1, 0.3, 3}},
        [](const double* v, physics::ScrewThermalParameters& s) { s.nut_heat_exponent = v[0]; }));
    bool torque = !runs.empty();
    for (const auto& r : runs) torque = torque && !r.torque_Nm.empty();
    // The motor's copper loss reaches the screw through the motor housing and
    // flange, minutes late: a first-order lag on τ², its time constant free.
    // It enters through the coupling, flange and fixed bearing's seat, over a
    // length that is free too (up to a quarter of the screw, 200 mm at most):
    // heat put into the end cell alone where it enters over 90 mm leaves a
    // structure along the first tenth of the axis that other candidates take.
    const double entryLimit_mm = runs.empty() || !runs.front().screw
                                     ? 200
                                     : std::min(200.0, runs.front().screw->length_mm / 4);
    if (torque)
        candidates.push_back(
            {.cause = QStringLiteral("motor_heat"),
             .parameters = {{QStringLiteral("c_motor"), QStringLiteral("W/(N·m)²"), 0.01, 0, 20},
                            {QStringLiteral("tau"), QStringLiteral("s"), 120, 1, 3600},
                            {QStringLiteral("entry"), QStringLiteral("mm"),
                             std::min(40.0, entryLimit_mm / 2), 0, entryLimit_mm}},
             .physics =
                 [](const double* v, physics::ScrewThermalParameters& s) {
                     s.c_motor_W_per_Nm2 = v[0];
                     s.motor_entry_m = v[2] * 1e-3;
                 },
             .inputs =
                 [](const double* v, ScrewRunInputs& in) {
                     std::vector<double>& q = in.mean_torque_squared_Nm2;
                     const double decay = std::exp(-in.dt_s / v[1]);
                     for (std::size_t k = 1; k < q.size(); ++k) q[k] += (q[k - 1] - q[k]) * decay;
                 }});

    // Sensor effects for every temperature sensor the model reads on the screw.
    if (!runs.empty())
        for (const auto& t : runs.front().temperatures) {
            if (!(t.role == ChannelRole::Nut ||
                  (t.role == ChannelRole::Bearing && t.position_mm)) ||
                !t.unusable.isEmpty())
                continue;
            candidates.push_back(
                onSensor(QStringLiteral("sensor_lag"), t.channel_id,
                         {QStringLiteral("tau"), QStringLiteral("s"), 60, 1, 7200},
                         [](double tau, const ScrewRunInputs& in, std::vector<double>& y,
                            std::size_t s) { firstOrderLag(in.sensors[s].time_s, y, tau); }));
            candidates.push_back(onSensor(
                QStringLiteral("sensor_offset"), t.channel_id,
                {QStringLiteral("offset"), QStringLiteral("K"), 0, -10, 10},
                [](double offset, const ScrewRunInputs&, std::vector<double>& y, std::size_t) {
                    for (double& v : y) v += offset;
                }));
        }
    // The room sensor is read as a temperature, not only as a rise: the screw
    // starts at the room temperature it soaked in, so a room sensor reading δ
    // high makes every screw sensor look δ low against the model, and the fit
    // bends its heat parameters to follow. Its gain is on the positioning
    // error the bent fit gets wrong. (Offsets on the air and structure
    // sensors cancel in their rises; InvisibleOffsets shows it.)
    // The room channel is the one the screw model reads (channelForRole).
    const auto channelOf = [&](ChannelRole role) {
        return models::channelForRole(runs.front(), role, QStringLiteral("heat-transfer"))
            .channel_id;
    };
    if (allRunsHave(runs, ChannelRole::Ambient))
        candidates.push_back(
            {.cause = QStringLiteral("sensor_offset:") + channelOf(ChannelRole::Ambient),
             .parameters = {{QStringLiteral("offset"), QStringLiteral("K"), 0, -10, 10}},
             .readings =
                 [](const double* v, const ScrewRunInputs&, const auto&, ScrewRunOutputs& out) {
                     for (auto& sensor : out.sensor_C)
                         for (double& t : sensor) t -= v[0];
                 },
             .output_only = true});
    // A late room sensor: the screw followed the room the sensor shows only
    // τ later. Lags on the air and structure sensors act only through
    // refraction and frame growth (the base model reads neither), so they
    // tell in the second step, on top of one of those.
    const auto lateSensor = [&](ChannelRole role, const QString& measures, const QString& onTopOf,
                                std::function<void(double, ScrewRunInputs&)> undo) {
        if (allRunsHave(runs, role))
            candidates.push_back(lateOffScrew(channelOf(role), measures, onTopOf, std::move(undo)));
    };
    lateSensor(ChannelRole::Ambient, QStringLiteral("room"), {}, roomBeforeItsSensor);
    lateSensor(ChannelRole::Air, QStringLiteral("air in the beam path"),
               QStringLiteral("air_refraction"),
               [](double tau, ScrewRunInputs& in) { riseBeforeItsSensor(in.air_rise_K, tau); });
    lateSensor(
        ChannelRole::Structure, QStringLiteral("structure"), QStringLiteral("frame_growth"),
        [](double tau, ScrewRunInputs& in) { riseBeforeItsSensor(in.structure_rise_K, tau); });
    if (allRunsHave(runs, ChannelRole::Air))
        candidates.push_back({.cause = QStringLiteral("air_refraction"),
                              .parameters = {{QStringLiteral("fraction"), QString(), 0, -5, 5}},
                              .readings =
                                  [](const double* v, const ScrewRunInputs& in, const auto& at,
                                     ScrewRunOutputs& out) {
                                      addToErrors(out, at, in.air_rise_K, in,
                                                  kEdlen_ppm_per_K * 1e-3 * v[0],
                                                  [&](double x) { return x + in.dead_path_mm; });
                                  },
                              .output_only = true});
    if (allRunsHave(runs, ChannelRole::Structure))
        // The structure is massive: its growth follows the measured surface
        // temperature with a lag of up to hours.
        candidates.push_back(
            {.cause = QStringLiteral("frame_growth"),
             .parameters = {{QStringLiteral("g"), QStringLiteral("µm/K"), 0, -50, 50},
                            {QStringLiteral("tau"), QStringLiteral("s"),
                             structureLagStart_s(runs, baseResiduals), 1, 6 * 3600}},
             .readings =
                 [](const double* v, const ScrewRunInputs& in, const auto& at,
                    ScrewRunOutputs& out) {
                     addToErrors(out, at, lagged(in.structure_rise_K, v[1]), in, v[0],
                                 [](double) { return 1.0; });
                 },
             .output_only = true});
    return candidates;
}

models::ScrewModelVariant extendedModel(const std::vector<CandidateEffect>& effects,
                                        const std::vector<double>& start) {
    models::ScrewModelVariant v = models::baseScrewModel();
    std::vector<std::size_t> offsets;
    for (const auto& e : effects) {
        offsets.push_back(v.parameters.size());
        v.parameters.insert(v.parameters.end(), e.parameters.begin(), e.parameters.end());
    }
    for (std::size_t i = 0; i < v.parameters.size() && i < start.size(); ++i)
        v.parameters[i].initial = start[i];
    const auto base = v.physics;
    v.physics = [base, effects, offsets](const double* p, physics::ScrewThermalParameters& s) {
        base(p, s);
        for (std::size_t e = 0; e < effects.size(); ++e)
            if (effects[e].physics) effects[e].physics(p + offsets[e], s);
    };
    bool inputs = false;
    for (const auto& e : effects) inputs = inputs || bool(e.inputs);
    if (inputs)
        v.inputs = [effects, offsets](const double* p, ScrewRunInputs& in) {
            for (std::size_t e = 0; e < effects.size(); ++e)
                if (effects[e].inputs) effects[e].inputs(p + offsets[e], in);
        };
    bool readings = false;
    for (const auto& e : effects) readings = readings || bool(e.readings);
    if (readings)
        v.readings = [effects, offsets](const double* p, const ScrewRunInputs& in,
                                        const std::vector<PredictionPoint>& at,
                                        ScrewRunOutputs& out) {
            for (std::size_t e = 0; e < effects.size(); ++e)
                if (effects[e].readings) effects[e].readings(p + offsets[e], in, at, out);
        };
    return v;
}

}  // namespace driftlab::diagnosis
