#include "core/rig/SimulatedAxisRun.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/domain/Channel.h"
#include "core/rig/AxisDrive.h"
#include "core/rig/SensorModel.h"

namespace driftlab::rig {
namespace {

constexpr double kEdlen_ppm_per_K = -0.95;  // refractive-index change of air per kelvin

double roundTo(double value, double quantum) {
    return std::round(value / quantum) * quantum;
}

/// Room temperature of one run: an offset and a slow swing with its own phase.
struct RoomTemperature {
    double offset_K, phase_rad;
    const EnvironmentSpec* env;
    double at(double t_s) const {
        return env->ambient_mean_C + offset_K +
               env->ambient_swing_K * std::sin(2 * M_PI * t_s / env->ambient_period_s + phase_rad);
    }
};

/// First-order lag stepped exactly for an input held over the step.
struct LaggedTemperature {
    double value_C, lag_s;
    void step(double target_C, double dt_s) {
        value_C = target_C + (value_C - target_C) * std::exp(-dt_s / lag_s);
    }
};

/// Cold geometric error of the axis (one per machine) and the interferometer's view of it.
struct InterferometerModel {
    InterferometerSpec spec;
    double pitch_phase_rad;
    double geometric_um(double x_mm) const {
        return spec.pitch_error_amplitude_um *
                   std::sin(2 * M_PI * x_mm / spec.pitch_error_period_mm + pitch_phase_rad) +
               spec.lead_error_um_per_m * x_mm * 1e-3;
    }
    double backlash_um(Direction d) const {
        return (d == Direction::Positive ? 0.5 : -0.5) * spec.backlash_um;
    }
};

}  // namespace

SampleSeries toSampleSeries(const RunOutput& out, const std::vector<QString>& columns) {
    SampleSeries series;
    series.time_s = out.time_s;
    series.columns = columns;
    const std::size_t rows = out.time_s.size(), width = columns.size();
    series.values.assign(width, std::vector<double>(rows));
    for (std::size_t r = 0; r < rows; ++r)
        for (std::size_t c = 0; c < width; ++c) series.values[c][r] = out.rows[r * width + c];
    return series;
}

double bearingSeat_mm(const physics::ScrewThermalParameters& p, bool fixedEnd) {
    return fixedEnd ? p.fixed_end_axis_mm + 2.5 : p.fixed_end_axis_mm + p.length_m * 1e3 - 2.5;
}

// The random draws happen in the order the rig has always drawn them, so a
// campaign of a seed is the same campaign before and after this class.
struct SimulatedAxisRun::State {
    const RigSpec& spec;
    std::vector<QString> columns;
    Programme programme;
    InterferometerModel interferometer;
    std::mt19937_64 rng;
    std::normal_distribution<double> gauss{0.0, 1.0};
    RoomTemperature room;
    physics::ScrewThermalModel screw;
    AxisDrive drive;
    LaggedTemperature air, structure;
    double air0_C, structure0_C;
    std::vector<SensorModel> sensors;
    std::vector<int> channelColumn;
    int positionColumn, feedColumn, torqueColumn;
    double fixedSeat_mm, freeSeat_mm;
    double t = 0, lastSample_s = 0, nextSample_s, torqueSquaredSinceSample = 0;
    std::size_t nextMeasurement = 0;
    bool started = false;
    std::function<void(const physics::ScrewThermalModel&)> observer;

    static RoomTemperature drawRoom(const EnvironmentSpec& env, std::mt19937_64& rng) {
        std::uniform_real_distribution<double> uniform(-1.0, 1.0);
        const double offset = env.run_offset_spread_K * uniform(rng);
        return {offset, M_PI * uniform(rng), &env};
    }

    State(const RigSpec& s, const physics::ScrewThermalParameters& p, std::vector<QString> cols,
          Programme prog, double pitchPhase_rad, unsigned seed)
        : spec(s),
          columns(std::move(cols)),
          programme(std::move(prog)),
          interferometer{s.interferometer, pitchPhase_rad},
          rng(seed),
          room(drawRoom(s.environment, rng)),
          screw(p, room.at(0)),
          drive(s.drive, p.lead_m * 1e3, static_cast<unsigned>(rng())),
          air{room.at(0) + 0.1, s.environment.air_lag_s},
          structure{room.at(0) - 0.2, s.environment.structure_lag_s},
          air0_C(air.value_C),
          structure0_C(structure.value_C),
          fixedSeat_mm(bearingSeat_mm(p, true)),
          freeSeat_mm(bearingSeat_mm(p, false)),
          nextSample_s(s.sample_interval_s) {
        auto columnOf = [&](const QString& id) {
            const auto it = std::find(columns.begin(), columns.end(), id);
            return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
        };
        for (const auto& name : spec.names.all()) {
            SensorSpec sensor;
            sensor.noise_K = spec.temperature_noise_K;
            sensor.dropout_probability = spec.dropout_probability;
            if (auto it = spec.effects.sensor_lag_s.find(name);
                it != spec.effects.sensor_lag_s.end())
                sensor.lag_s = it->second;
            if (auto it = spec.effects.sensor_offset_K.find(name);
                it != spec.effects.sensor_offset_K.end())
                sensor.offset_K = it->second;
            sensors.emplace_back(sensor, static_cast<unsigned>(rng()));
            channelColumn.push_back(columnOf(name));
        }
        positionColumn = columnOf(kPositionColumn);
        feedColumn = columnOf(kFeedColumn);
        torqueColumn = columnOf(kTorqueColumn);
    }

    void logSample(double at_s, RunOutput& out) {
        const AxisState axis = axisStateAt(programme.motion, at_s);
        // Bearing-seat sensors read the screw where they sit (docs/physics.md).
        const double truth[] = {screw.temperatureUnderNut_C(axis.position_mm),
                                screw.temperatureAt_C(screw.screwCoordinate_m(fixedSeat_mm)),
                                screw.temperatureAt_C(screw.screwCoordinate_m(freeSeat_mm)),
                                room.at(at_s),
                                air.value_C,
                                structure.value_C};
        const double dt = at_s - lastSample_s;
        // Columns this run does not log (the spindle channels) stay empty.
        const std::size_t first = out.rows.size();
        out.rows.resize(first + columns.size(), std::numeric_limits<double>::quiet_NaN());
        double* row = out.rows.data() + first;
        auto set = [&](int column, double value) {
            if (column >= 0) row[column] = value;
        };
        for (std::size_t c = 0; c < sensors.size(); ++c)
            set(channelColumn[c], sensors[c].read(truth[c], dt));
        set(positionColumn, roundTo(axis.position_mm, 0.001));
        set(feedColumn, axis.feed_mm_min);
        set(torqueColumn, roundTo(drive.loggedTorque_Nm(torqueSquaredSinceSample, dt), 0.001));
        torqueSquaredSinceSample = 0;
        out.time_s.push_back(at_s);
        lastSample_s = at_s;
        if (observer) observer(screw);
    }

    void measure(const MeasurementEvent& e, RunOutput& out) {
        const double deviation =
            interferometer.geometric_um(e.target_mm) + interferometer.backlash_um(e.direction) +
            screw.thermalError_um(e.target_mm) +
            spec.effects.frame_growth_um_per_K * (structure.value_C - structure0_C) +
            spec.effects.air_refraction * kEdlen_ppm_per_K * (air.value_C - air0_C) *
                (e.target_mm + interferometer.spec.dead_path_mm) * 1e-3 +
            interferometer.spec.noise_um * gauss(rng);
        out.readings.push_back(
            {e.time_s, e.cycle, e.target_mm, e.direction, roundTo(deviation, 0.001)});
    }

    void step(RunOutput& out) {
        const EnvironmentSpec& env = spec.environment;
        const std::span<const MotionSegment> motion(programme.motion);
        const double dt = std::min(spec.physics_step_s, programme.duration_s - t);
        const double t1 = t + dt;
        physics::StepConditions conditions;
        conditions.dt_s = dt;
        conditions.ambient_begin_C = room.at(t);
        conditions.ambient_end_C = room.at(t1);
        conditions.motion = motion;
        const double torqueSquared = drive.torqueSquaredIntegral(motion, t, t1);
        torqueSquaredSinceSample += torqueSquared;
        conditions.mean_torque_squared_Nm2 = torqueSquared / dt;
        screw.step(conditions);
        const auto& cells = screw.temperatures_C();
        double meanScrew = 0;
        for (double c : cells) meanScrew += c;
        meanScrew /= static_cast<double>(cells.size());
        const double amb = room.at(t1);
        air.step(amb + 0.1 + env.air_screw_coupling * (meanScrew - amb), dt);
        structure.step(amb - 0.2 + env.structure_screw_coupling * (meanScrew - amb), dt);
        t = t1;
        // Readings are taken while the nut dwells at the target, so the state
        // at the end of the step holding the reading is the state it sees.
        const auto& measurements = programme.measurements;
        while (nextMeasurement < measurements.size() &&
               measurements[nextMeasurement].time_s <= t + 1e-9)
            measure(measurements[nextMeasurement++], out);
        if (t >= nextSample_s - 1e-9) {
            logSample(roundTo(t, 1e-6), out);
            nextSample_s += spec.sample_interval_s;
        }
    }
};

SimulatedAxisRun::SimulatedAxisRun(const RigSpec& spec,
                                   const physics::ScrewThermalParameters& screw,
                                   std::vector<QString> columns, Programme programme,
                                   double pitchPhase_rad, unsigned seed)
    : m(std::make_unique<State>(spec, screw, std::move(columns), std::move(programme),
                                pitchPhase_rad, seed)) {}

SimulatedAxisRun::~SimulatedAxisRun() = default;

void SimulatedAxisRun::advanceTo(double until_s, RunOutput& out) {
    if (!m->started) {
        m->started = true;
        m->logSample(0, out);
    }
    while (m->t < m->programme.duration_s - 1e-9 && m->t < until_s - 1e-9) m->step(out);
}

double SimulatedAxisRun::time_s() const {
    return m->t;
}
double SimulatedAxisRun::duration_s() const {
    return m->programme.duration_s;
}
bool SimulatedAxisRun::finished() const {
    return m->started && m->t >= m->programme.duration_s - 1e-9;
}
const Programme& SimulatedAxisRun::programme() const {
    return m->programme;
}
void SimulatedAxisRun::replaceProgramme(Programme programme) {
    m->programme = std::move(programme);
}
void SimulatedAxisRun::setSampleObserver(
    std::function<void(const physics::ScrewThermalModel&)> observer) {
    m->observer = std::move(observer);
}

}  // namespace driftlab::rig
