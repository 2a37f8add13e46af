#include "core/rig/CampaignSimulator.h"

#include <QSet>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/rig/AxisDrive.h"
#include "core/rig/ModuleOutage.h"
#include "core/rig/MovingStateProgramme.h"
#include "core/rig/SimulatedAxisRun.h"
#include "core/rig/SpindleTestSimulator.h"

namespace driftlab::rig {
namespace {

struct RunContext {
    const RigSpec& spec;
    const physics::ScrewThermalParameters& screw;
    const std::vector<QString>& columns;
    double pitchPhase_rad;
    const SimulationCallbacks& callbacks;
    double totalSimulated_s;
    double doneBefore_s;
};

void validateSpec(const RigSpec& spec, const physics::ScrewThermalParameters& screw) {
    screw.validate();
    if (spec.runs.empty() && spec.spindle_runs < 1)
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
    for (int k = 1; k <= spec.spindle_runs; ++k) ids.insert(QStringLiteral("SP%1").arg(k));
    for (const ModuleOutage& o : spec.module_outages) {
        if (!ids.contains(o.run_id))
            throw std::invalid_argument("simulated rig: module outage in run '" +
                                        o.run_id.toStdString() + "', which the rig does not run");
        if (!(o.from_s >= 0 && o.from_s < o.to_s))
            throw std::invalid_argument(
                QStringLiteral("simulated rig: module outage in run %1 from %2 s to %3 s: it "
                               "must start at 0 s or later and end after it starts")
                    .arg(o.run_id)
                    .arg(o.from_s)
                    .arg(o.to_s)
                    .toStdString());
    }
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
    SimulatedAxisRun axis(spec, ctx.screw, ctx.columns, buildMovingStateProgramme(programmeSpec),
                          ctx.pitchPhase_rad, runSeed);
    run.motion = axis.programme().motion;
    if (ctx.callbacks.sample)
        axis.setSampleObserver(
            [&](const physics::ScrewThermalModel& screw) { ctx.callbacks.sample(run.id, screw); });

    RunOutput out;
    const double chunk_s = 600 * spec.physics_step_s;
    while (!axis.finished()) {
        axis.advanceTo(axis.time_s() + chunk_s, out);
        if (ctx.callbacks.progress && !axis.finished() &&
            !ctx.callbacks.progress((ctx.doneBefore_s + axis.time_s()) / ctx.totalSimulated_s))
            throw SimulationCancelled();
    }
    run.samples = toSampleSeries(out, ctx.columns);
    run.positioning = std::move(out.readings);
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

Campaign rigCampaignHeader(const RigSpec& spec, bool withSpindleChannels) {
    const physics::ScrewThermalParameters screw = effectiveScrewParameters(spec);
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
    if (withSpindleChannels)
        for (auto& c : spindleTestChannels()) campaign.channels.push_back(c);
    for (const auto& c : campaign.channels) campaign.sample_columns.push_back(c.id);
    campaign.sample_columns.insert(campaign.sample_columns.end(),
                                   {kPositionColumn, kFeedColumn, kTorqueColumn});
    return campaign;
}

Campaign simulateCampaign(const RigSpec& spec, const SimulationCallbacks& callbacks) {
    const physics::ScrewThermalParameters screw = effectiveScrewParameters(spec);
    validateSpec(spec, screw);
    Campaign campaign = rigCampaignHeader(spec, spec.spindle_runs > 0);

    std::mt19937_64 rng(spec.seed);
    const double pitchPhase_rad = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
    double total_s = 0;
    for (const auto& r : spec.runs) total_s += r.warmup_s + r.cooldown_s;
    double done_s = 0;
    for (const auto& state : spec.runs) {
        const RunContext ctx{spec,           screw,     campaign.sample_columns,
                             pitchPhase_rad, callbacks, std::max(total_s, 1.0),
                             done_s};
        campaign.runs.push_back(simulateMovingRun(ctx, state, static_cast<unsigned>(rng())));
        done_s += state.warmup_s + state.cooldown_s;
    }
    for (int k = 1; k <= spec.spindle_runs; ++k) {
        SpindleTestSpec spindle = spindleTestProgramme(k);
        spindle.seed = static_cast<unsigned>(rng());
        spindle.probe_noise_um = spec.probe_noise_um;
        campaign.runs.push_back(simulateSpindleTest(spindle, campaign.sample_columns));
    }
    // The module's outages last: the sensors were read through them, so every
    // draw and every lag state after an outage is that of the run without it.
    const auto temperature = temperatureColumns(campaign.channels, campaign.sample_columns);
    for (Run& run : campaign.runs)
        blankOutages(outagesOf(spec.module_outages, run.id), temperature, run.samples);
    if (callbacks.progress) callbacks.progress(1.0);
    return campaign;
}

}  // namespace driftlab::rig
