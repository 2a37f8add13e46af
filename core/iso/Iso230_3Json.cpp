#include "core/iso/Iso230_3Json.h"

#include <QJsonArray>
#include <cmath>

namespace driftlab::iso {
namespace {

QJsonValue jsonNumber(double value) {
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue();
}

QString sign(Direction d) {
    return d == Direction::Positive ? QStringLiteral("+") : QStringLiteral("-");
}

QJsonObject seriesJson(const DriftSeries& s) {
    return {{QStringLiteral("max_drift_um"), picometres(s.max_drift_um)},
            {QStringLiteral("max_drift_time_s"), s.max_drift_time_s},
            {QStringLiteral("range_um"), picometres(s.range_um)},
            {QStringLiteral("final_drift_um"), picometres(s.final_drift_um)},
            {QStringLiteral("stabilised"), s.stabilised()},
            {QStringLiteral("stabilised_time_s"), jsonNumber(s.stabilised_time_s)}};
}

QJsonObject axisJson(const AxisDriftEvaluation& e) {
    QJsonArray targets;
    for (const TargetDrift& t : e.targets) {
        QJsonObject o = seriesJson(t.drift);
        o[QStringLiteral("target_mm")] = t.target_mm;
        o[QStringLiteral("direction")] = sign(t.direction);
        QJsonArray time_s, drift_um;
        for (std::size_t i = 0; i < t.drift.time_s.size(); ++i) {
            time_s.append(t.drift.time_s[i]);
            drift_um.append(picometres(t.drift.drift_um[i]));
        }
        o[QStringLiteral("time_s")] = time_s;
        o[QStringLiteral("drift_um")] = drift_um;
        targets.append(o);
    }
    // The axis zero and far end, by direction, so that scripts need not search the targets.
    auto end = [&](double at_mm) {
        QJsonObject o{{QStringLiteral("target_mm"), at_mm}};
        for (Direction d : {Direction::Positive, Direction::Negative})
            if (const TargetDrift* t = e.find(at_mm, d)) o[sign(d)] = seriesJson(t->drift);
        return o;
    };
    const TargetDrift& max = e.targets[std::size_t(e.max_index)];
    return {{QStringLiteral("evaluation"), QStringLiteral("moving linear axis")},
            {QStringLiteral("zero"), end(e.zero_mm)},
            {QStringLiteral("far_end"), end(e.far_end_mm)},
            {QStringLiteral("cycles"), e.cycles},
            {QStringLiteral("zero_mm"), e.zero_mm},
            {QStringLiteral("far_end_mm"), e.far_end_mm},
            {QStringLiteral("max_drift_um"), picometres(e.max_drift_um)},
            {QStringLiteral("max_drift_target_mm"), max.target_mm},
            {QStringLiteral("max_drift_direction"), sign(max.direction)},
            {QStringLiteral("max_drift_time_s"), max.drift.max_drift_time_s},
            {QStringLiteral("stabilised"), !std::isnan(e.stabilised_time_s)},
            {QStringLiteral("stabilised_time_s"), jsonNumber(e.stabilised_time_s)},
            {QStringLiteral("targets"), targets},
            {QStringLiteral("warnings"), QJsonArray::fromStringList(e.warnings)}};
}

QJsonObject probesJson(const ProbeDriftEvaluation& e) {
    QJsonArray probes, tilts;
    for (const ProbeDrift& p : e.probes) {
        QJsonObject o = seriesJson(p.drift);
        o[QStringLiteral("channel")] = p.channel_id;
        o[QStringLiteral("role")] = toString(p.role);
        o[QStringLiteral("samples")] = int(p.drift.time_s.size());
        probes.append(o);
    }
    for (const TiltDrift& t : e.tilts) {
        QJsonObject o = seriesJson(t.drift);
        o[QStringLiteral("name")] = t.name;
        o[QStringLiteral("from")] = t.from;
        o[QStringLiteral("to")] = t.to;
        o[QStringLiteral("max_tilt_urad")] = picometres(t.max_tilt_urad);
        o[QStringLiteral("range_urad")] = picometres(t.range_urad);
        tilts.append(o);
    }
    return {{QStringLiteral("evaluation"), QStringLiteral("drift probes")},
            {QStringLiteral("probes"), probes},
            {QStringLiteral("tilts"), tilts},
            {QStringLiteral("stabilised"), !std::isnan(e.stabilised_time_s)},
            {QStringLiteral("stabilised_time_s"), jsonNumber(e.stabilised_time_s)},
            {QStringLiteral("notes"), QJsonArray::fromStringList(e.notes)},
            {QStringLiteral("warnings"), QJsonArray::fromStringList(e.warnings)}};
}

}  // namespace

bool hasAxisDrift(const Run& run) {
    return isFeedAxisRun(run.kind) && !run.positioning.empty();
}

bool hasProbeDrift(const Run& run) {
    return run.kind == RunKind::Spindle || run.kind == RunKind::Etve;
}

QStringList RunDrift::warnings() const {
    return axis ? axis->warnings : probes ? probes->warnings : QStringList{};
}

DriftFigures RunDrift::figures() const {
    return axis ? driftFigures(*axis) : driftFigures(*probes);
}

RunDrift evaluateRunDrift(const Campaign& campaign, const Run& run, const DriftSettings& settings) {
    RunDrift out;
    if (hasAxisDrift(run)) {
        out.axis = evaluateAxisDrift(run, settings);
        out.error = out.axis->error;
    } else if (hasProbeDrift(run)) {
        out.probes = evaluateProbeDrift(campaign, run, settings);
        out.error = out.probes->error;
    } else {
        out.error = QStringLiteral(
                        "run %1 (%2) has no drift to evaluate: it is neither a "
                        "feed-axis run with positioning readings nor a spindle or "
                        "ETVE run")
                        .arg(run.id, toString(run.kind));
    }
    return out;
}

double picometres(double value_um) {
    return std::round(value_um * 1e6) / 1e6;
}

QJsonObject runDriftJson(const RunDrift& drift) {
    return drift.axis ? axisJson(*drift.axis) : probesJson(*drift.probes);
}

}  // namespace driftlab::iso
