#include "core/procedures/ProcedurePlan.h"

#include <QStringList>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "core/domain/MessageText.h"

namespace driftlab::procedures {
namespace {

QString rangeText(const RangeMm& r) {
    return QStringLiteral("%1–%2 mm").arg(numberText(r.from_mm), numberText(r.to_mm));
}

void requireInside(const RangeMm& r, const RangeMm& travel_mm, const QString& what) {
    if (r.from_mm < travel_mm.from_mm || r.to_mm > travel_mm.to_mm)
        throw std::invalid_argument(QStringLiteral("%1: range %2 is outside the travel %3")
                                        .arg(what, rangeText(r), rangeText(travel_mm))
                                        .toStdString());
}

PlannedRun positioningRun(const Procedure& p, const PositioningSpec& s) {
    requireInside({s.span_mm.from_mm - s.overrun_mm, s.span_mm.to_mm + s.overrun_mm}, p.travel_mm,
                  QStringLiteral("positioning span with its overrun"));
    PlannedRun run;
    run.id = s.run_id;
    run.kind = RunKind::Positioning;
    run.feed_mm_min = s.feed_mm_min;
    run.range_mm = s.span_mm;
    run.programme = buildPositioningProgramme(s);
    run.duration_s = run.programme.duration_s;
    run.description =
        QStringLiteral(
            "ISO 230-2 positioning: %1 targets over %2, %3 bidirectional %4 cycles at "
            "%5 mm/min, overrun %6 mm, reading after %7 s dwell")
            .arg(positioningTargets(s).size())
            .arg(rangeText(s.span_mm))
            .arg(s.cycles)
            .arg(s.order == ApproachOrder::Linear ? QStringLiteral("linear")
                                                  : QStringLiteral("pilgrim"))
            .arg(numberText(s.feed_mm_min), numberText(s.overrun_mm), numberText(s.dwell_s));
    return run;
}

PlannedRun thermalDistortionRun(const Procedure& p, const ThermalDistortionSpec& s) {
    requireInside(s.range_mm, p.travel_mm, QStringLiteral("thermal distortion"));
    rig::MovingStateSpec ms;
    ms.feed_mm_min = s.feed_mm_min;
    ms.range_mm = s.range_mm;
    ms.warmup_s = s.max_warmup_s;  // the longest; the engine may end it early
    ms.cooldown_s = s.cooldown_s;
    ms.block_s = s.interval_s;
    ms.cooldown_interval_s = s.cooldown_interval_s;
    ms.targets_mm = rig::equallySpacedTargets(p.travel_mm, s.targets, s.overrun_mm);
    ms.pass_feed_mm_min = s.pass_feed_mm_min;
    ms.dwell_s = s.dwell_s;
    ms.overrun_mm = s.overrun_mm;
    PlannedRun run;
    run.id = s.run_id;
    run.kind = RunKind::Moving;
    run.feed_mm_min = s.feed_mm_min;
    run.range_mm = s.range_mm;
    run.programme = rig::buildMovingStateProgramme(ms);
    run.warmup = ms;
    run.stabilisation_um = s.stabilisation_um;
    run.duration_s = run.programme.duration_s;
    run.description = QStringLiteral(
                          "ISO 230-3 thermal distortion of the axis: reciprocating over %1 at %2 "
                          "mm/min, a pass over %3 targets every %4 s until two passes differ by at "
                          "most %5 µm (at most %6 s), then %7 s cool-down")
                          .arg(rangeText(s.range_mm), numberText(s.feed_mm_min))
                          .arg(s.targets)
                          .arg(numberText(s.interval_s), numberText(s.stabilisation_um),
                               numberText(s.max_warmup_s), numberText(s.cooldown_s));
    return run;
}

PlannedRun speedProgrammeRun(const Procedure& p, const QString& id, RunKind kind,
                             const std::vector<SpindleBlock>& blocks) {
    PlannedRun run;
    run.id = id;
    run.kind = kind;
    rig::SpindleTestSpec spec;
    spec.run_id = id;
    spec.kind = kind;
    spec.sample_interval_s = p.sample_interval_s;
    spec.blocks.clear();
    QStringList speeds;
    for (const SpindleBlock& b : blocks) {
        spec.blocks.push_back({b.duration_s, b.speed_rpm});
        run.duration_s += b.duration_s;
        speeds << (b.speed_rpm == 0 ? QStringLiteral("stop %1 s").arg(numberText(b.duration_s))
                                    : QStringLiteral("%1 rpm %2 s")
                                          .arg(numberText(b.speed_rpm), numberText(b.duration_s)));
    }
    run.spindle = spec;
    run.description =
        kind == RunKind::Etve
            ? QStringLiteral(
                  "ETVE: machine at rest for %1 s while the room varies; drift probes "
                  "and temperatures logged")
                  .arg(numberText(run.duration_s))
            : QStringLiteral("ISO 230-3 spindle speed programme (%1), five drift probes")
                  .arg(speeds.join(QStringLiteral(", ")));
    return run;
}

PlannedRun movingStateRun(const Procedure& p, const MovingStatesSpec& s,
                          const MovingStateStep& step) {
    requireInside(step.range_mm, p.travel_mm, QStringLiteral("moving state ") + step.run_id);
    rig::MovingStateSpec ms;
    ms.feed_mm_min = step.feed_mm_min;
    ms.range_mm = step.range_mm;
    ms.warmup_s = step.warmup_s;
    ms.cooldown_s = step.cooldown_s;
    ms.block_s = s.block_s;
    ms.cooldown_interval_s = s.cooldown_interval_s;
    ms.targets_mm = rig::equallySpacedTargets(p.travel_mm, s.targets, ms.overrun_mm);
    PlannedRun run;
    run.id = step.run_id;
    run.kind = RunKind::Moving;
    run.feed_mm_min = step.feed_mm_min;
    run.range_mm = step.range_mm;
    run.programme = rig::buildMovingStateProgramme(ms);
    run.duration_s = run.programme.duration_s;
    run.description =
        QStringLiteral("moving state: %1 mm/min over %2, %3 s warm-up, %4 s cool-down")
            .arg(numberText(step.feed_mm_min), rangeText(step.range_mm), numberText(step.warmup_s),
                 numberText(step.cooldown_s));
    return run;
}

}  // namespace

std::vector<PlannedRun> planRuns(const Procedure& procedure) {
    const Procedure& p = procedure;
    auto missing = [&]() {
        return std::invalid_argument("procedure of kind " + toString(p.kind).toStdString() +
                                     " has no spec for it");
    };
    switch (p.kind) {
        case ProcedureKind::Iso230_2:
            if (!p.positioning) throw missing();
            return {positioningRun(p, *p.positioning)};
        case ProcedureKind::Iso230_3Axis:
            if (!p.thermal_distortion) throw missing();
            return {thermalDistortionRun(p, *p.thermal_distortion)};
        case ProcedureKind::Etve:
            if (!p.etve) throw missing();
            return {speedProgrammeRun(p, p.etve->run_id, RunKind::Etve, {{p.etve->duration_s, 0}})};
        case ProcedureKind::Spindle:
            if (!p.spindle) throw missing();
            return {speedProgrammeRun(p, p.spindle->run_id, RunKind::Spindle, p.spindle->blocks)};
        case ProcedureKind::MovingStates: {
            if (!p.moving_states) throw missing();
            std::vector<PlannedRun> runs;
            for (const MovingStateStep& step : p.moving_states->states)
                runs.push_back(movingStateRun(p, *p.moving_states, step));
            return runs;
        }
    }
    return {};
}

PlannedRun replanWarmupEnd(const PlannedRun& run, double warmupEnd_s) {
    if (!run.warmup) throw std::invalid_argument("replanWarmupEnd: the run has no warm-up spec");
    if (!(warmupEnd_s > 0) || warmupEnd_s > run.warmup->warmup_s)
        throw std::invalid_argument("replanWarmupEnd: the end must be within the planned warm-up");
    PlannedRun shorter = run;
    shorter.warmup->warmup_s = warmupEnd_s;
    // The builder's warm-up loop only looks at warmup_s when a block would
    // reach it, so every block and pass before warmupEnd_s is unchanged.
    shorter.programme = rig::buildMovingStateProgramme(*shorter.warmup);
    shorter.duration_s = shorter.programme.duration_s;
    shorter.description =
        run.description +
        QStringLiteral("; stabilised, warm-up ended at %1 s").arg(numberText(warmupEnd_s));
    return shorter;
}

std::optional<double> passChange_um(const std::vector<PositioningMeasurement>& readings) {
    // A target is matched to 1 nm, so 10.0000000001 and 10 are the same target.
    using Key = std::pair<long long, Direction>;
    std::map<int, std::map<Key, double>> byCycle;
    std::set<Key> allKeys;
    for (const PositioningMeasurement& m : readings) {
        if (m.cycle < 1) continue;  // cycle 0 is the cold reference, not a warm-up pass
        const Key key{std::llround(m.target_mm * 1e6), m.direction};
        byCycle[m.cycle][key] = m.deviation_um;
        allKeys.insert(key);
    }
    std::vector<const std::map<Key, double>*> complete;
    for (const auto& [cycle, values] : byCycle)
        if (values.size() == allKeys.size()) complete.push_back(&values);
    if (complete.size() < 2) return std::nullopt;
    const auto& last = *complete.back();
    const auto& before = *complete[complete.size() - 2];
    double change_um = 0;
    for (const auto& [key, deviation_um] : last)
        change_um = std::max(change_um, std::abs(deviation_um - before.at(key)));
    return change_um;
}

}  // namespace driftlab::procedures
