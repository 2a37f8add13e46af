#include "core/procedures/ProcedureSpecsJson.h"

#include <QJsonArray>
#include <QSet>

#include "core/procedures/ProcedureJsonReader.h"
#include "core/rig/MovingStateProgramme.h"

namespace driftlab::procedures {
namespace {

const QStringList kOrders{QStringLiteral("linear"), QStringLiteral("pilgrim")};
/// More ISO 230-2 targets than any axis is measured at, each a reading per
/// cycle and direction; far below what a pass's int count and memory hold.
constexpr double kMaxPositioningTargets = 100000;

QJsonArray rangeJson(const RangeMm& r) {
    return {r.from_mm, r.to_mm};
}

/// The targets of a pass are spaced over the travel inside it by the overrun.
void checkOverrunLeavesRoom(const ObjectReader& r, const QString& key, double overrun_mm,
                            const RangeMm& travel_mm) {
    if (2 * overrun_mm >= travel_mm.to_mm - travel_mm.from_mm)
        r.fail(key, QStringLiteral("%1 mm on each side leaves no room for targets in the travel")
                        .arg(overrun_mm));
}

}  // namespace

PositioningSpec readPositioning(const QJsonObject& json, const QString& path,
                                const RangeMm& travel_mm) {
    ObjectReader r(json, path,
                   {"run_id", "span_mm", "targets_per_metre", "irregularity", "seed", "cycles",
                    "order", "feed_mm_min", "overrun_mm", "dwell_s"});
    PositioningSpec s;
    r.runId("run_id", s.run_id);
    r.range("span_mm", s.span_mm, &travel_mm);
    r.number("targets_per_metre", s.targets_per_metre);
    if (s.targets_per_metre < 5)
        r.fail("targets_per_metre",
               QStringLiteral("ISO 230-2 asks for at least 5 targets per metre, got %1")
                   .arg(s.targets_per_metre));
    // Checked before positioningTargets() builds them: a density or span typed
    // a few digits too long would overflow its int count and ask for gigabytes.
    const double count = s.targets_per_metre * (s.span_mm.to_mm - s.span_mm.from_mm) / 1000;
    if (!(count <= kMaxPositioningTargets))
        r.fail("targets_per_metre", QStringLiteral("%1 per metre over the span [%2, %3] mm is "
                                                   "more than %4 targets")
                                        .arg(s.targets_per_metre)
                                        .arg(s.span_mm.from_mm)
                                        .arg(s.span_mm.to_mm)
                                        .arg(kMaxPositioningTargets));
    r.nonNegative("irregularity", s.irregularity);
    if (s.irregularity >= 0.1)
        r.fail("irregularity", QStringLiteral("must be below 0.1 (10 %% of the interval), got %1")
                                   .arg(s.irregularity));
    r.seed("seed", s.seed);
    r.integerAtLeast("cycles", s.cycles, 1);
    int order = int(s.order);
    r.choice("order", order, kOrders);
    s.order = ApproachOrder(order);
    r.positive("feed_mm_min", s.feed_mm_min);
    // Positive: without an overrun there is no reversal before the other direction.
    r.positive("overrun_mm", s.overrun_mm);
    if (s.span_mm.from_mm - s.overrun_mm < travel_mm.from_mm ||
        s.span_mm.to_mm + s.overrun_mm > travel_mm.to_mm)
        r.fail("overrun_mm", QStringLiteral("%1 mm past the span [%2, %3] mm leaves the travel")
                                 .arg(s.overrun_mm)
                                 .arg(s.span_mm.from_mm)
                                 .arg(s.span_mm.to_mm));
    r.nonNegative("dwell_s", s.dwell_s);
    const std::vector<double> targets = positioningTargets(s);
    for (std::size_t i = 1; i < targets.size(); ++i)
        if (!(targets[i] > targets[i - 1]))
            r.fail("span_mm", QStringLiteral("too short for distinct targets at 0.001 mm"));
    return s;
}

ThermalDistortionSpec readThermalDistortion(const QJsonObject& json, const QString& path,
                                            const RangeMm& travel_mm) {
    ObjectReader r(json, path,
                   {"run_id", "feed_mm_min", "range_mm", "targets", "interval_s",
                    "stabilisation_um", "max_warmup_s", "cooldown_s", "cooldown_interval_s",
                    "pass_feed_mm_min", "dwell_s", "overrun_mm"});
    ThermalDistortionSpec s;
    r.runId("run_id", s.run_id);
    r.positive("feed_mm_min", s.feed_mm_min);
    r.range("range_mm", s.range_mm, &travel_mm);
    r.integerAtLeast("targets", s.targets, 2);
    r.positive("interval_s", s.interval_s);
    r.positive("stabilisation_um", s.stabilisation_um);
    r.positive("max_warmup_s", s.max_warmup_s);
    r.nonNegative("cooldown_s", s.cooldown_s);
    r.positive("cooldown_interval_s", s.cooldown_interval_s);
    r.positive("pass_feed_mm_min", s.pass_feed_mm_min);
    r.nonNegative("dwell_s", s.dwell_s);
    r.nonNegative("overrun_mm", s.overrun_mm);
    checkOverrunLeavesRoom(r, "overrun_mm", s.overrun_mm, travel_mm);
    return s;
}

EtveSpec readEtve(const QJsonObject& json, const QString& path) {
    ObjectReader r(json, path, {"run_id", "duration_s"});
    EtveSpec s;
    r.runId("run_id", s.run_id);
    r.positive("duration_s", s.duration_s);
    return s;
}

SpindleSpec readSpindle(const QJsonObject& json, const QString& path) {
    ObjectReader r(json, path, {"run_id", "blocks"});
    SpindleSpec s;
    r.runId("run_id", s.run_id);
    if (r.has("blocks")) {
        const QJsonArray blocks = r.array("blocks");
        if (blocks.isEmpty()) r.fail("blocks", QStringLiteral("must hold at least one block"));
        s.blocks.clear();
        for (qsizetype i = 0; i < blocks.size(); ++i) {
            const QString at = r.pathOf(QStringLiteral("blocks[%1]").arg(i));
            if (!blocks[i].isObject())
                throw ProcedureError{at + QStringLiteral(": must be an object, got ") +
                                     describeJsonValue(blocks[i])};
            ObjectReader b(blocks[i].toObject(), at, {"duration_s", "speed_rpm"});
            SpindleBlock block;
            if (!b.has("duration_s")) b.fail("duration_s", QStringLiteral("is required"));
            b.positive("duration_s", block.duration_s);
            b.nonNegative("speed_rpm", block.speed_rpm);
            s.blocks.push_back(block);
        }
    }
    return s;
}

MovingStatesSpec readMovingStates(const QJsonObject& json, const QString& path,
                                  const RangeMm& travel_mm) {
    ObjectReader r(json, path, {"states", "targets", "block_s", "cooldown_interval_s"});
    MovingStatesSpec s;
    const QJsonArray states = r.array("states");
    if (states.isEmpty()) r.fail("states", QStringLiteral("must list at least one moving state"));
    QSet<QString> ids;
    for (qsizetype i = 0; i < states.size(); ++i) {
        const QString at = r.pathOf(QStringLiteral("states[%1]").arg(i));
        if (!states[i].isObject())
            throw ProcedureError{at + QStringLiteral(": must be an object, got ") +
                                 describeJsonValue(states[i])};
        ObjectReader st(states[i].toObject(), at,
                        {"run_id", "feed_mm_min", "range_mm", "warmup_s", "cooldown_s"});
        MovingStateStep step;
        st.string("run_id", step.run_id, true);
        st.runId("run_id", step.run_id);
        if (ids.contains(step.run_id))
            st.fail("run_id",
                    QStringLiteral("\"%1\" is used by an earlier state").arg(step.run_id));
        ids.insert(step.run_id);
        st.positive("feed_mm_min", step.feed_mm_min);
        st.range("range_mm", step.range_mm, &travel_mm);
        st.positive("warmup_s", step.warmup_s);
        st.nonNegative("cooldown_s", step.cooldown_s);
        s.states.push_back(step);
    }
    r.integerAtLeast("targets", s.targets, 2);
    r.positive("block_s", s.block_s);
    r.positive("cooldown_interval_s", s.cooldown_interval_s);
    checkOverrunLeavesRoom(r, "states", rig::MovingStateSpec{}.overrun_mm, travel_mm);
    return s;
}

QJsonObject toJson(const PositioningSpec& s) {
    return {{"run_id", s.run_id},
            {"span_mm", rangeJson(s.span_mm)},
            {"targets_per_metre", s.targets_per_metre},
            {"irregularity", s.irregularity},
            {"seed", double(s.seed)},
            {"cycles", s.cycles},
            {"order", kOrders[int(s.order)]},
            {"feed_mm_min", s.feed_mm_min},
            {"overrun_mm", s.overrun_mm},
            {"dwell_s", s.dwell_s}};
}

QJsonObject toJson(const ThermalDistortionSpec& s) {
    return {{"run_id", s.run_id},
            {"feed_mm_min", s.feed_mm_min},
            {"range_mm", rangeJson(s.range_mm)},
            {"targets", s.targets},
            {"interval_s", s.interval_s},
            {"stabilisation_um", s.stabilisation_um},
            {"max_warmup_s", s.max_warmup_s},
            {"cooldown_s", s.cooldown_s},
            {"cooldown_interval_s", s.cooldown_interval_s},
            {"pass_feed_mm_min", s.pass_feed_mm_min},
            {"dwell_s", s.dwell_s},
            {"overrun_mm", s.overrun_mm}};
}

QJsonObject toJson(const EtveSpec& s) {
    return {{"run_id", s.run_id}, {"duration_s", s.duration_s}};
}

QJsonObject toJson(const SpindleSpec& s) {
    QJsonArray blocks;
    for (const SpindleBlock& b : s.blocks)
        blocks.append(QJsonObject{{"duration_s", b.duration_s}, {"speed_rpm", b.speed_rpm}});
    return {{"run_id", s.run_id}, {"blocks", blocks}};
}

QJsonObject toJson(const MovingStatesSpec& s) {
    QJsonArray states;
    for (const MovingStateStep& st : s.states)
        states.append(QJsonObject{{"run_id", st.run_id},
                                  {"feed_mm_min", st.feed_mm_min},
                                  {"range_mm", rangeJson(st.range_mm)},
                                  {"warmup_s", st.warmup_s},
                                  {"cooldown_s", st.cooldown_s}});
    return {{"states", states},
            {"targets", s.targets},
            {"block_s", s.block_s},
            {"cooldown_interval_s", s.cooldown_interval_s}};
}

}  // namespace driftlab::procedures
