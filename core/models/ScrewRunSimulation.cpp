#include "core/models/ScrewRunSimulation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/models/DriveTorque.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"
#include "core/physics/NutHeatDeposition.h"
#include "core/rig/MovingStateProgramme.h"

namespace driftlab::models {
namespace {

double lastTime(const RunData& run) {
    double end = 0;
    for (const auto& o : run.observations) end = std::max(end, o.time_s);
    for (const auto& t : run.temperatures)
        if (!t.rise_K.empty()) end = std::max(end, t.rise_K.time_s.back());
    if (!run.motion.empty()) end = std::max(end, run.motion.back().end_s);
    return end;
}

}  // namespace

physics::ScrewThermalParameters screwParameters(const RunData& run,
                                                const physics::ScrewThermalParameters& coefficients,
                                                int cells) {
    physics::ScrewThermalParameters p = coefficients;
    const Screw& s = *run.screw;
    p.length_m = s.length_mm * 1e-3;
    p.diameter_m = s.diameter_mm * 1e-3;
    p.lead_m = s.lead_mm * 1e-3;
    p.fixed_end_axis_mm = s.fixed_end_mm;
    p.alpha_per_K = s.alpha_per_K;
    p.nut_length_m = run.nut_length_mm.value_or(s.diameter_mm * 2) * 1e-3;
    p.cells = cells;
    return p;
}

ScrewRunInputs prepareScrewRun(const RunData& run, double dt_s, const QString& model,
                               RoomInput room, int cells) {
    if (!run.screw)
        throw ModelError(
            QStringLiteral("model '%1' simulates the screw; the campaign has none").arg(model));
    ScrewRunInputs in;
    in.run_id = run.run_id;
    in.dt_s = dt_s;
    in.duration_s = lastTime(run);
    in.motion = run.motion;
    if (in.motion.empty()) {
        if (run.position_mm.time_s.size() < 2)
            throw ModelError(QStringLiteral("run '%1' has neither motion segments nor a position "
                                            "column; model '%2' needs the nut's motion")
                                 .arg(run.run_id, model));
        in.motion =
            physics::motionFromPositionSamples(run.position_mm.time_s, run.position_mm.value,
                                               run.feed_mm_min.time_s, run.feed_mm_min.value);
    }

    const auto steps = static_cast<std::size_t>(std::ceil(in.duration_s / dt_s - 1e-9));
    if (cells > 0) {
        try {
            in.nut_path = std::make_shared<const physics::NutPath>(screwParameters(run, {}, cells),
                                                                   in.motion, dt_s, steps);
        } catch (const std::invalid_argument&) {
            // Motion off the screw: each simulation refuses it at its step, as
            // without a path.
        }
    }

    if (!run.torque_Nm.empty())
        in.mean_torque_squared_Nm2 = meanTorqueSquaredPerStep(run, in.motion, steps, dt_s);

    if (run.interferometer) in.dead_path_mm = run.interferometer->dead_path_mm;
    // RoomOnly reads the first usable room channel, the one the sensorless
    // model names as its input.
    const TemperatureRise* loggedRoom =
        room == RoomInput::RoomOnly ? firstUsableOfRole(run, ChannelRole::Ambient) : nullptr;
    if (room == RoomInput::Steady || (room == RoomInput::RoomOnly && !loggedRoom)) {
        // Only rises matter (the error is relative to the run's start), so any
        // steady room will do.
        in.ambient_C.assign(steps + 1, in.initial_C);
        return in;
    }

    const TemperatureRise& ambient =
        loggedRoom ? *loggedRoom : channelForRole(run, ChannelRole::Ambient, model);
    // Through a hole in the room's log the screw keeps simulating on the
    // bridge; the observations inside a hole left out are not scored.
    requireCoverage(run, ambient.rise_K);
    in.ambient_C.resize(steps + 1);
    for (std::size_t k = 0; k <= steps; ++k)
        in.ambient_C[k] =
            ambient.reference_C +
            bridgedValueAt(ambient.rise_K, std::min(double(k) * dt_s, in.duration_s), run.run_id);
    // The screw starts at the room temperature it soaked in. Not at its own
    // sensors' first readings: a sensor offset would shift the whole run.
    in.initial_C = ambient.reference_C;
    if (room == RoomInput::RoomOnly) return in;
    if (const TemperatureRise* air = firstUsableOfRole(run, ChannelRole::Air))
        in.air_rise_K = air->rise_K;
    if (const TemperatureRise* structure = firstUsableOfRole(run, ChannelRole::Structure))
        in.structure_rise_K = structure->rise_K;
    for (const TemperatureRise& t : run.temperatures) {
        const bool onScrew = t.role == ChannelRole::Nut ||
                             (t.role == ChannelRole::Bearing && t.position_mm.has_value());
        if (!onScrew || !t.unusable.isEmpty() || t.rise_K.empty()) continue;
        ScrewSensorSeries series{t.channel_id, t.role, t.position_mm.value_or(0), {}, {}};
        for (std::size_t i = 0; i < t.rise_K.time_s.size(); ++i) {
            if (t.rise_K.time_s[i] > in.duration_s) break;
            series.time_s.push_back(t.rise_K.time_s[i]);
            series.measured_C.push_back(t.reference_C + t.rise_K.value[i]);
        }
        in.sensors.push_back(std::move(series));
    }

    return in;
}

ScrewRunOutputs simulateScrewRun(const ScrewRunInputs& in,
                                 const physics::ScrewThermalParameters& parameters,
                                 const std::vector<PredictionPoint>& points) {
    physics::ScrewThermalModel screw(parameters, in.initial_C);
    ScrewRunOutputs out;
    out.error_um.assign(points.size(), 0.0);
    out.sensor_C.resize(in.sensors.size());
    for (std::size_t s = 0; s < in.sensors.size(); ++s)
        out.sensor_C[s].resize(in.sensors[s].time_s.size());

    // Every point and sample is read at the end of the step that holds it.
    // Readings are taken while the nut dwells and sensors are sampled on step
    // ends, so this costs less than the noise (checked against dt → 0 in the tests).
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](auto a, auto b) { return points[a].time_s < points[b].time_s; });
    std::size_t nextPoint = 0;
    std::vector<std::size_t> nextSample(in.sensors.size(), 0);
    std::vector<double> xs;

    const std::size_t steps = in.ambient_C.size() - 1;
    physics::StepConditions step;
    step.motion = in.motion;
    step.dt_s = in.dt_s;
    if (in.nut_path && in.nut_path->fits(parameters, in.dt_s, in.motion.size(), steps))
        step.nut_path = in.nut_path.get();
    for (std::size_t k = 0; k <= steps; ++k) {
        if (k > 0) {
            step.ambient_begin_C = in.ambient_C[k - 1];
            step.ambient_end_C = in.ambient_C[k];
            step.mean_torque_squared_Nm2 =
                in.mean_torque_squared_Nm2.empty() ? 0.0 : in.mean_torque_squared_Nm2[k - 1];
            step.nut_path_step = k - 1;
            screw.step(step);
        }
        const double end_s = k == steps ? INFINITY : double(k) * in.dt_s + 1e-9;
        xs.clear();
        std::size_t upto = nextPoint;
        for (; upto < order.size() && points[order[upto]].time_s <= end_s; ++upto)
            xs.push_back(points[order[upto]].position_mm);
        if (!xs.empty()) {
            const auto error = screw.thermalError_um(xs);
            for (std::size_t j = nextPoint; j < upto; ++j)
                out.error_um[order[j]] = error[j - nextPoint];
            nextPoint = upto;
        }
        for (std::size_t s = 0; s < in.sensors.size(); ++s) {
            const auto& series = in.sensors[s];
            for (auto& i = nextSample[s]; i < series.time_s.size() && series.time_s[i] <= end_s;
                 ++i)
                out.sensor_C[s][i] =
                    series.role == ChannelRole::Nut
                        ? screw.temperatureUnderNut_C(
                              rig::axisStateAt(in.motion, series.time_s[i]).position_mm)
                        : screw.temperatureAt_C(screw.screwCoordinate_m(series.position_mm));
        }
    }
    return out;
}

}  // namespace driftlab::models
