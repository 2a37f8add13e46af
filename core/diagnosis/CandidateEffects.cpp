#include "core/diagnosis/CandidateEffects.h"

#include <cmath>

#include "core/models/RunDataAccess.h"

namespace driftlab::diagnosis {
namespace {

using models::FreeParameter;
using models::PredictionPoint;
using models::ScrewModelVariant;
using models::ScrewRunInputs;
using models::ScrewRunOutputs;

CandidateEffect extend(const QString& cause, const QString& channel, FreeParameter extra,
                       const std::vector<double>& baseValues) {
    CandidateEffect c{cause, channel, models::baseScrewModel(), extra};
    for (std::size_t i = 0; i < c.variant.parameters.size() && i < baseValues.size(); ++i)
        c.variant.parameters[i].initial = baseValues[i];
    c.variant.parameters.push_back(extra);
    return c;
}

/// A physical extension: the extra value goes into the simulation.
CandidateEffect physical(const QString& cause, FreeParameter extra,
                         const std::vector<double>& baseValues,
                         void (*apply)(double, physics::ScrewThermalParameters&)) {
    CandidateEffect c = extend(cause, {}, extra, baseValues);
    const auto base = c.variant.physics;
    c.variant.physics = [base, apply](const double* p, physics::ScrewThermalParameters& s) {
        base(p, s);
        apply(p[3], s);
    };
    return c;
}

/// A reading extension: the simulation is the base one, the readings change.
CandidateEffect reading(const QString& cause, const QString& channel, FreeParameter extra,
                        const std::vector<double>& baseValues,
                        std::function<void(double, const ScrewRunInputs&,
                                           const std::vector<PredictionPoint>&, ScrewRunOutputs&)>
                            apply) {
    CandidateEffect c = extend(cause, channel, extra, baseValues);
    c.variant.readings = [apply](const double* p, const ScrewRunInputs& in,
                                 const std::vector<PredictionPoint>& at,
                                 ScrewRunOutputs& out) { apply(p[3], in, at, out); };
    return c;
}

/// Index of a sensor series by channel, or -1.
int sensorIndex(const ScrewRunInputs& in, const QString& channel) {
    for (std::size_t s = 0; s < in.sensors.size(); ++s)
        if (in.sensors[s].channel_id == channel) return int(s);
    return -1;
}

/// The interferometer reading moves by gain(t, x)·value at every point.
void addToErrors(ScrewRunOutputs& out, const std::vector<PredictionPoint>& at,
                 const models::Signal& rise, const ScrewRunInputs& in, double perKelvin_um,
                 const std::function<double(double x_mm)>& pathFactor) {
    if (rise.empty()) return;
    for (std::size_t j = 0; j < at.size(); ++j)
        out.error_um[j] += perKelvin_um * pathFactor(at[j].position_mm) *
                           models::valueAt(rise, at[j].time_s, in.max_gap_s, in.run_id);
}

}  // namespace

std::vector<CandidateEffect> candidateEffects(const std::vector<models::RunData>& runs,
                                              const std::vector<double>& baseValues) {
    std::vector<CandidateEffect> candidates;
    candidates.push_back(
        physical(QStringLiteral("forced_convection"),
                 {QStringLiteral("h1"), QStringLiteral("W/(m²·K) per rad/s"), 0.01, 0, 2},
                 baseValues, [](double v, physics::ScrewThermalParameters& s) {
                     s.h1_forced_W_m2K = v;
                     s.forced_exponent = 1;
                 }));
    candidates.push_back(physical(
        QStringLiteral("nut_heat_exponent"), {QStringLiteral("n"), QString(), 1, 0.3, 3},
        baseValues, [](double v, physics::ScrewThermalParameters& s) { s.nut_heat_exponent = v; }));
    bool torque = !runs.empty();
    bool air = !runs.empty(), structure = !runs.empty();
    for (const auto& r : runs) {
        torque = torque && !r.torque_Nm.empty();
        bool hasAir = false, hasStructure = false;
        for (const auto& t : r.temperatures) {
            hasAir = hasAir || (t.role == ChannelRole::Air && t.unusable.isEmpty());
            hasStructure =
                hasStructure || (t.role == ChannelRole::Structure && t.unusable.isEmpty());
        }
        air = air && hasAir;
        structure = structure && hasStructure;
    }
    if (torque)
        candidates.push_back(physical(
            QStringLiteral("motor_heat"),
            {QStringLiteral("c_motor"), QStringLiteral("W/(N·m)²"), 0.01, 0, 20}, baseValues,
            [](double v, physics::ScrewThermalParameters& s) { s.c_motor_W_per_Nm2 = v; }));

    // Sensor effects for every temperature sensor the model reads on the screw.
    QStringList screwSensors;
    if (!runs.empty())
        for (const auto& t : runs.front().temperatures)
            if ((t.role == ChannelRole::Nut || (t.role == ChannelRole::Bearing && t.position_mm)) &&
                t.unusable.isEmpty())
                screwSensors << t.channel_id;
    for (const QString& ch : screwSensors) {
        candidates.push_back(
            reading(QStringLiteral("sensor_lag:") + ch, ch,
                    {QStringLiteral("tau"), QStringLiteral("s"), 60, 1, 7200}, baseValues,
                    [ch](double tau, const ScrewRunInputs& in, const auto&, ScrewRunOutputs& out) {
                        const int s = sensorIndex(in, ch);
                        if (s < 0) return;
                        auto& y = out.sensor_C[std::size_t(s)];
                        const auto& t = in.sensors[std::size_t(s)].time_s;
                        // Exactly as a first-order sensor follows its part between samples.
                        for (std::size_t k = 1; k < y.size(); ++k)
                            y[k] = y[k] + (y[k - 1] - y[k]) * std::exp(-(t[k] - t[k - 1]) / tau);
                    }));
        candidates.push_back(reading(
            QStringLiteral("sensor_offset:") + ch, ch,
            {QStringLiteral("offset"), QStringLiteral("K"), 0, -10, 10}, baseValues,
            [ch](double offset, const ScrewRunInputs& in, const auto&, ScrewRunOutputs& out) {
                const int s = sensorIndex(in, ch);
                if (s < 0) return;
                for (double& v : out.sensor_C[std::size_t(s)]) v += offset;
            }));
    }
    if (air)
        candidates.push_back(reading(
            QStringLiteral("air_refraction"), {}, {QStringLiteral("fraction"), QString(), 0, -5, 5},
            baseValues,
            [](double fraction, const ScrewRunInputs& in, const auto& at, ScrewRunOutputs& out) {
                addToErrors(out, at, in.air_rise_K, in, kEdlen_ppm_per_K * 1e-3 * fraction,
                            [&](double x) { return x + in.dead_path_mm; });
            }));
    if (structure)
        candidates.push_back(reading(
            QStringLiteral("frame_growth"), {},
            {QStringLiteral("g"), QStringLiteral("µm/K"), 0, -50, 50}, baseValues,
            [](double g, const ScrewRunInputs& in, const auto& at, ScrewRunOutputs& out) {
                addToErrors(out, at, in.structure_rise_K, in, g, [](double) { return 1.0; });
            }));
    return candidates;
}

}  // namespace driftlab::diagnosis
