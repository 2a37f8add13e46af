#include "core/rig/CampaignSimulator.h"

#include <QSet>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/rig/AxisDrive.h"
#include "core/rig/MovingStateProgramme.h"
#include "core/rig/SensorModel.h"
#include "core/rig/SpindleTestSimulator.h"

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

struct RunContext {
    const RigSpec& spec;
    const physics::ScrewThermalParameters& screw;
    const std::vector<QString>& columns;
    const InterferometerModel& interferometer;
    const SimulationCallbacks& callbacks;
    double totalSimulated_s;
    double doneBefore_s;
};

/// Bearing-seat sensors sit 2.5 mm inside the screw ends.
double bearingSeat_mm(const physics::ScrewThermalParameters& p, bool fixedEnd) {
    return fixedEnd ? p.fixed_end_axis_mm + 2.5 : p.fixed_end_axis_mm + p.length_m * 1e3 - 2.5;
}

void validateSpec(const RigSpec& spec, const physics::ScrewThermalParameters& screw) {
    screw.validate();
    if (spec.runs.empty() && !spec.spindle_run)
        throw std::invalid_argument("simulated rig: no runs to simulate");
    if (!(spec.sample_interval_s > 0) || !(spec.physics_step_s > 0))
        throw std::invalid_argument(
            "simulated rig: sample interval and physics step must be positive");
    if (spec.targets < 2) throw std::invalid_argument("simulated rig: at least 2 targets");
    const double screwFrom = screw.fixed_end_axis_mm;
    const double screwTo = screwFrom + screw.length_m * 1e3;
    // The nut never leaves the travel (the passes' targets sit inside it by
    // their overrun), so the travel must lie on the screw.
    if (spec.travel_mm.from_mm < screwFrom || spec.travel_mm.to_mm > screwTo)
        throw std::invalid_argument(QStringLiteral("simulated rig: travel %1–%2 mm is not on the "
                                                   "screw, which runs %3–%4 mm")
                                        .arg(spec.travel_mm.from_mm)
                                        .arg(spec.travel_mm.to_mm)
                                        .arg(screwFrom)
                                        .arg(screwTo)
                                        .toStdString());
    QSet<QString> ids;
    for (const auto& run : spec.runs) {
        if (!isValidIdentifier(run.id) || ids.contains(run.id))
            throw std::invalid_argument("simulated rig: run id '" + run.id.toStdString() +
                                        "' is empty, invalid or used twice");
        ids.insert(run.id);
        if (run.range_mm.from_mm < spec.travel_mm.from_mm ||
            run.range_mm.to_mm > spec.travel_mm.to_mm)
            throw std::invalid_argument(
                QStringLiteral(
                    "simulated rig: run %1: range %2–%3 mm is outside the travel %4–%5 mm")
                    .arg(run.id)
                    .arg(run.range_mm.from_mm)
                    .arg(run.range_mm.to_mm)
                    .arg(spec.travel_mm.from_mm)
                    .arg(spec.travel_mm.to_mm)
                    .toStdString());
    }
    const auto names = spec.names.all();
    auto checkChannel = [&](const char* effect, const QString& channel) {
        if (std::find(names.begin(), names.end(), channel) == names.end())
            throw std::invalid_argument(
                QStringLiteral("simulated rig: effect %1:%2: the rig has no temperature channel "
                               "'%2' (it has %3)")
                    .arg(QLatin1String(effect), channel,
                         QStringList(names.begin(), names.end()).join(QStringLiteral(", ")))
                    .toStdString());
    };
    for (const auto& [channel, lag] : spec.effects.sensor_lag_s)
        checkChannel("sensor_lag", channel);
    for (const auto& [channel, offset] : spec.effects.sensor_offset_K)
        checkChannel("sensor_offset", channel);
}

Run simulateMovingRun(const RunContext& ctx, const MovingStateRun& state, unsigned runSeed) {
    const RigSpec& spec = ctx.spec;
    MovingStateSpec programmeSpec;
    programmeSpec.feed_mm_min = state.feed_mm_min;
    programmeSpec.range_mm = state.range_mm;
    programmeSpec.warmup_s = state.warmup_s;
    programmeSpec.cooldown_s = state.cooldown_s;
    // Targets inside the travel by the overrun, so the pass never leaves it.
    programmeSpec.targets_mm =
        equallySpacedTargets(spec.travel_mm, spec.targets, programmeSpec.overrun_mm);
    const Programme programme = buildMovingStateProgramme(programmeSpec);
    const std::span<const MotionSegment> motion(programme.motion);

    std::mt19937_64 rng(runSeed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    const EnvironmentSpec& env = spec.environment;
    const RoomTemperature room{env.run_offset_spread_K * uniform(rng), M_PI * uniform(rng), &env};

    physics::ScrewThermalModel screw(ctx.screw, room.at(0));
    AxisDrive drive(spec.drive, ctx.screw.lead_m * 1e3, static_cast<unsigned>(rng()));
    LaggedTemperature air{room.at(0) + 0.1, env.air_lag_s};
    LaggedTemperature structure{room.at(0) - 0.2, env.structure_lag_s};
    const double air0 = air.value_C, structure0 = structure.value_C;

    const auto names = spec.names.all();
    std::vector<SensorModel> sensors;
    for (const auto& name : names) {
        SensorSpec s;
        s.noise_K = spec.temperature_noise_K;
        s.dropout_probability = spec.dropout_probability;
        if (auto it = spec.effects.sensor_lag_s.find(name); it != spec.effects.sensor_lag_s.end())
            s.lag_s = it->second;
        if (auto it = spec.effects.sensor_offset_K.find(name);
            it != spec.effects.sensor_offset_K.end())
            s.offset_K = it->second;
        sensors.emplace_back(s, static_cast<unsigned>(rng()));
    }

    Run run;
    run.id = state.id;
    run.kind = RunKind::Moving;
    run.feed_mm_min = state.feed_mm_min;
    run.range_mm = state.range_mm;
    run.description = QStringLiteral(
                          "simulated: warm-up %1 min at %2 mm/min over %3–%4 mm, then "
                          "%5 min cool-down")
                          .arg(state.warmup_s / 60)
                          .arg(state.feed_mm_min)
                          .arg(state.range_mm.from_mm)
                          .arg(state.range_mm.to_mm)
                          .arg(state.cooldown_s / 60);
    run.motion = programme.motion;
    run.samples.columns = ctx.columns;
    run.samples.values.assign(ctx.columns.size(), {});
    std::vector<int> channelColumn;
    for (const auto& name : names) channelColumn.push_back(run.samples.columnIndex(name));
    const int positionColumn = run.samples.columnIndex(kPositionColumn);
    const int feedColumn = run.samples.columnIndex(kFeedColumn);
    const int torqueColumn = run.samples.columnIndex(kTorqueColumn);

    const double fixedSeat_mm = bearingSeat_mm(ctx.screw, true);
    const double freeSeat_mm = bearingSeat_mm(ctx.screw, false);
    double lastSample_s = 0;
    double torqueSquaredSinceSample = 0;
    auto logSample = [&](double t) {
        const AxisState axis = axisStateAt(programme.motion, t);
        // Bearing-seat sensors read the screw where they sit (DESIGN.md §4).
        const double truth[] = {screw.temperatureUnderNut_C(axis.position_mm),
                                screw.temperatureAt_C(screw.screwCoordinate_m(fixedSeat_mm)),
                                screw.temperatureAt_C(screw.screwCoordinate_m(freeSeat_mm)),
                                room.at(t),
                                air.value_C,
                                structure.value_C};
        const double dt = t - lastSample_s;
        // Columns this run does not log (the spindle channels) stay empty.
        for (auto& column : run.samples.values)
            column.push_back(std::numeric_limits<double>::quiet_NaN());
        auto set = [&](int column, double value) {
            run.samples.values[static_cast<std::size_t>(column)].back() = value;
        };
        for (std::size_t c = 0; c < names.size(); ++c)
            set(channelColumn[c], sensors[c].read(truth[c], dt));
        set(positionColumn, roundTo(axis.position_mm, 0.001));
        set(feedColumn, axis.feed_mm_min);
        set(torqueColumn, roundTo(drive.loggedTorque_Nm(torqueSquaredSinceSample, dt), 0.001));
        torqueSquaredSinceSample = 0;
        run.samples.time_s.push_back(t);
        lastSample_s = t;
        if (ctx.callbacks.sample) ctx.callbacks.sample(run.id, screw);
    };

    const auto& measurements = programme.measurements;
    std::size_t nextMeasurement = 0;
    const InterferometerModel& ifm = ctx.interferometer;
    const double deadPath_mm = ifm.spec.dead_path_mm;
    auto measure = [&](const MeasurementEvent& e) {
        double deviation = ifm.geometric_um(e.target_mm) + ifm.backlash_um(e.direction) +
                           screw.thermalError_um(e.target_mm) +
                           spec.effects.frame_growth_um_per_K * (structure.value_C - structure0) +
                           spec.effects.air_refraction * kEdlen_ppm_per_K * (air.value_C - air0) *
                               (e.target_mm + deadPath_mm) * 1e-3 +
                           ifm.spec.noise_um * gauss(rng);
        run.positioning.push_back(
            {e.time_s, e.cycle, e.target_mm, e.direction, roundTo(deviation, 0.001)});
    };

    logSample(0);
    double nextSample_s = spec.sample_interval_s;
    const double duration = programme.duration_s;
    double t = 0;
    int stepsSinceProgress = 0;
    while (t < duration - 1e-9) {
        const double dt = std::min(spec.physics_step_s, duration - t);
        const double t1 = t + dt;
        physics::StepConditions step;
        step.dt_s = dt;
        step.ambient_begin_C = room.at(t);
        step.ambient_end_C = room.at(t1);
        step.motion = motion;
        const double torqueSquared = drive.torqueSquaredIntegral(motion, t, t1);
        torqueSquaredSinceSample += torqueSquared;
        step.mean_torque_squared_Nm2 = torqueSquared / dt;
        screw.step(step);
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
        while (nextMeasurement < measurements.size() &&
               measurements[nextMeasurement].time_s <= t + 1e-9)
            measure(measurements[nextMeasurement++]);
        if (t >= nextSample_s - 1e-9) {
            logSample(roundTo(t, 1e-6));
            nextSample_s += spec.sample_interval_s;
        }
        if (ctx.callbacks.progress && ++stepsSinceProgress >= 600) {
            stepsSinceProgress = 0;
            if (!ctx.callbacks.progress((ctx.doneBefore_s + t) / ctx.totalSimulated_s))
                throw SimulationCancelled();
        }
    }
    return run;
}

Screw domainScrew(const physics::ScrewThermalParameters& p) {
    Screw s;
    s.length_mm = p.length_m * 1e3;
    s.diameter_mm = p.diameter_m * 1e3;
    s.lead_mm = p.lead_m * 1e3;
    s.fixed_end_mm = p.fixed_end_axis_mm;
    s.mounting = QStringLiteral("fixed-supported");
    s.alpha_per_K = p.alpha_per_K;
    s.density_kg_m3 = p.density_kg_m3;
    s.specific_heat_J_kgK = p.specific_heat_J_kgK;
    s.conductivity_W_mK = p.conductivity_W_mK;
    return s;
}

std::vector<Channel> rigChannels(const RigSpec& spec, const physics::ScrewThermalParameters& p) {
    const auto& n = spec.names;
    auto channel = [](const QString& id, ChannelRole role, const char* where,
                      std::optional<double> position_mm = {}) {
        return Channel{id, Quantity::Temperature, role, QString::fromLatin1(where), position_mm,
                       {}};
    };
    const double fixedSeat = bearingSeat_mm(p, true);
    const double freeSeat = bearingSeat_mm(p, false);
    return {channel(n.nut, ChannelRole::Nut, "nut flank"),
            channel(n.bearing_fixed, ChannelRole::Bearing, "fixed bearing seat", fixedSeat),
            channel(n.bearing_free, ChannelRole::Bearing, "support bearing seat", freeSeat),
            channel(n.ambient, ChannelRole::Ambient, "room, 1 m from the machine"),
            channel(n.air, ChannelRole::Air, "laser beam path"),
            channel(n.structure, ChannelRole::Structure, "machine bed")};
}

}  // namespace

physics::ScrewThermalParameters effectiveScrewParameters(const RigSpec& spec) {
    physics::ScrewThermalParameters p = spec.screw;
    p.h1_forced_W_m2K += spec.effects.forced_convection_h1;
    p.nut_heat_exponent = spec.effects.nut_heat_exponent;
    p.c_motor_W_per_Nm2 += spec.effects.motor_heat_W_per_Nm2;
    return p;
}

Campaign simulateCampaign(const RigSpec& spec, const SimulationCallbacks& callbacks) {
    const physics::ScrewThermalParameters screw = effectiveScrewParameters(spec);
    validateSpec(spec, screw);

    Campaign campaign;
    campaign.name = spec.campaign_name;
    campaign.machine = {QStringLiteral("DriftLab simulated rig"),
                        QStringLiteral("X"),
                        QStringLiteral("driftlab-sim"),
                        {}};
    campaign.screw = domainScrew(screw);
    campaign.nut_length_mm = screw.nut_length_m * 1e3;
    campaign.travel_mm = spec.travel_mm;
    campaign.interferometer = Interferometer{spec.interferometer.dead_path_mm, true, {}};
    campaign.channels = rigChannels(spec, screw);
    if (spec.spindle_run)
        for (auto& c : spindleTestChannels()) campaign.channels.push_back(c);
    for (const auto& c : campaign.channels) campaign.sample_columns.push_back(c.id);
    campaign.sample_columns.insert(campaign.sample_columns.end(),
                                   {kPositionColumn, kFeedColumn, kTorqueColumn});

    std::mt19937_64 rng(spec.seed);
    const InterferometerModel interferometer{
        spec.interferometer, std::uniform_real_distribution<double>(0, 2 * M_PI)(rng)};
    double total_s = 0;
    for (const auto& r : spec.runs) total_s += r.warmup_s + r.cooldown_s;
    double done_s = 0;
    for (const auto& state : spec.runs) {
        const RunContext ctx{spec,           screw,     campaign.sample_columns,
                             interferometer, callbacks, std::max(total_s, 1.0),
                             done_s};
        campaign.runs.push_back(simulateMovingRun(ctx, state, static_cast<unsigned>(rng())));
        done_s += state.warmup_s + state.cooldown_s;
    }
    if (spec.spindle_run) {
        SpindleTestSpec spindle;
        spindle.seed = static_cast<unsigned>(rng());
        campaign.runs.push_back(simulateSpindleTest(spindle, campaign.sample_columns));
    }
    if (callbacks.progress) callbacks.progress(1.0);
    return campaign;
}

}  // namespace driftlab::rig
