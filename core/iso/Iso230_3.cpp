#include "core/iso/Iso230_3.h"

#include <algorithm>
#include <set>

#include "core/domain/MessageText.h"

namespace driftlab::iso {

bool DriftSettings::isValid(QString* why) const {
    QString reason;
    if (!std::isfinite(window_s) || window_s <= 0)
        reason = QStringLiteral("stabilisation window W must be a positive number of s, not %1")
                     .arg(window_s);
    else if (!std::isfinite(tolerance_um) || tolerance_um <= 0)
        reason = QStringLiteral("stabilisation tolerance D must be a positive number of µm, not %1")
                     .arg(tolerance_um);
    else if (!std::isfinite(target_tolerance_mm) || target_tolerance_mm < 0)
        reason = QStringLiteral("target tolerance must be a non-negative number of mm");
    else if (probe_distance_mm && (!std::isfinite(*probe_distance_mm) || *probe_distance_mm <= 0))
        reason = QStringLiteral("probe distance must be a positive number of mm, not %1")
                     .arg(*probe_distance_mm);
    if (why) *why = reason;
    return reason.isEmpty();
}

namespace {

/// Whether the drift varies by less than D over [t_i, t_i + W], cut at the
/// last sample. The drift is linear between samples, so the window's extremes
/// are among the samples inside it and the interpolated value at its end:
/// sparse readings (cycles further apart than W) are judged by their rate.
bool windowWithin(const DriftSeries& s, std::size_t i, const DriftSettings& settings) {
    const double end_s = std::min(s.time_s[i] + settings.window_s, s.time_s.back());
    double lo = s.drift_um[i], hi = s.drift_um[i];
    for (std::size_t j = i + 1; j < s.time_s.size(); ++j) {
        double value = s.drift_um[j];
        if (s.time_s[j] > end_s) {
            const double span_s = s.time_s[j] - s.time_s[j - 1];
            const double f = (end_s - s.time_s[j - 1]) / span_s;
            value = s.drift_um[j - 1] + f * (s.drift_um[j] - s.drift_um[j - 1]);
        }
        lo = std::min(lo, value);
        hi = std::max(hi, value);
        if (s.time_s[j] >= end_s) break;
    }
    return hi - lo < settings.tolerance_um;
}

QString quotedDirection(Direction d) {
    return d == Direction::Positive ? QStringLiteral("'+'") : QStringLiteral("'-'");
}

/// The readings of one target, merged within the target tolerance.
struct TargetGroup {
    double target_mm = 0;
    std::vector<const PositioningMeasurement*> readings;
};

std::vector<TargetGroup> groupByTarget(const Run& run, double tolerance_mm) {
    std::vector<const PositioningMeasurement*> sorted;
    for (const PositioningMeasurement& m : run.positioning) sorted.push_back(&m);
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto* a, const auto* b) { return a->target_mm < b->target_mm; });
    std::vector<TargetGroup> groups;
    for (const PositioningMeasurement* m : sorted) {
        if (groups.empty() || m->target_mm - groups.back().target_mm > tolerance_mm)
            groups.push_back({m->target_mm, {}});
        groups.back().readings.push_back(m);
    }
    return groups;
}

/// The drift of one target and direction; an error names the target when
/// cycle 0 does not give it exactly one reference reading.
std::optional<TargetDrift> targetDrift(const TargetGroup& group, Direction direction,
                                       const DriftSettings& settings, QString* error) {
    std::vector<const PositioningMeasurement*> readings;
    for (const auto* m : group.readings)
        if (m->direction == direction) readings.push_back(m);
    if (readings.empty()) return std::nullopt;  // a unidirectional run: nothing to evaluate
    const auto references = std::count_if(readings.begin(), readings.end(),
                                          [](const auto* m) { return m->cycle == 0; });
    if (references != 1) {
        *error = QStringLiteral("target %1 mm, direction %2: %3 in cycle 0 (the cold reference)")
                     .arg(numberText(group.target_mm), quotedDirection(direction),
                          references == 0 ? QStringLiteral("no reading")
                                          : QStringLiteral("%1 readings").arg(references));
        return std::nullopt;
    }
    const double reference_um = (*std::find_if(readings.begin(), readings.end(), [](const auto* m) {
                                    return m->cycle == 0;
                                }))->deviation_um;
    std::stable_sort(readings.begin(), readings.end(), [](const auto* a, const auto* b) {
        return a->time_s < b->time_s || (a->time_s == b->time_s && a->cycle < b->cycle);
    });
    TargetDrift t{group.target_mm, direction, {}, {}};
    for (const auto* m : readings) {
        t.cycles.push_back(m->cycle);
        t.drift.time_s.push_back(m->time_s);
        t.drift.drift_um.push_back(m->deviation_um - reference_um);
    }
    summarise(t.drift, settings);
    return t;
}

/// The latest stabilisation of the series, or NaN when one is not stabilised.
template <typename Items, typename Series>
double latestStabilisation(const Items& items, Series series) {
    double latest_s = -std::numeric_limits<double>::infinity();
    for (const auto& item : items) {
        const DriftSeries& s = series(item);
        if (!s.stabilised()) return kNotStabilised;
        latest_s = std::max(latest_s, s.stabilised_time_s);
    }
    return items.empty() ? kNotStabilised : latest_s;
}

}  // namespace

void summarise(DriftSeries& s, const DriftSettings& settings) {
    s.stabilised_time_s = kNotStabilised;
    if (s.time_s.empty()) return;
    s.max_drift_um = s.drift_um.front();
    s.max_drift_time_s = s.time_s.front();
    s.min_um = s.max_um = s.drift_um.front();
    for (std::size_t i = 0; i < s.drift_um.size(); ++i) {
        const double d = s.drift_um[i];
        if (std::abs(d) > std::abs(s.max_drift_um)) {
            s.max_drift_um = d;
            s.max_drift_time_s = s.time_s[i];
        }
        s.min_um = std::min(s.min_um, d);
        s.max_um = std::max(s.max_um, d);
    }
    s.range_um = s.max_um - s.min_um;
    s.final_drift_um = s.drift_um.back();
    // Scanning back from the end: every window from the candidate on must be
    // within D, so the candidate is the sample after the last failing window.
    std::size_t candidate = s.time_s.size();
    while (candidate > 0 && windowWithin(s, candidate - 1, settings)) --candidate;
    // A stable tail shorter than W is no evidence: the drift may still move.
    if (candidate < s.time_s.size() && s.time_s.back() - s.time_s[candidate] >= settings.window_s)
        s.stabilised_time_s = s.time_s[candidate];
}

const TargetDrift* AxisDriftEvaluation::find(double target_mm, Direction direction) const {
    for (const TargetDrift& t : targets)
        if (t.direction == direction &&
            std::abs(t.target_mm - target_mm) <= settings.target_tolerance_mm)
            return &t;
    return nullptr;
}

AxisDriftEvaluation evaluateAxisDrift(const Run& run, const DriftSettings& settings) {
    AxisDriftEvaluation result;
    result.run_id = run.id;
    result.settings = settings;
    const QString prefix = QStringLiteral("run %1: ").arg(run.id);
    QString why;
    if (!settings.isValid(&why)) {
        result.error = prefix + why;
        return result;
    }
    if (run.positioning.empty()) {
        result.error = prefix + QStringLiteral("no positioning readings");
        return result;
    }
    std::set<int> cycles;
    for (const PositioningMeasurement& m : run.positioning) cycles.insert(m.cycle);
    result.cycles = int(cycles.size());
    if (!cycles.count(0)) {
        result.error = prefix + QStringLiteral(
                                    "no cycle 0 (the cold reference) among its "
                                    "positioning readings (cycles %1 to %2)")
                                    .arg(*cycles.begin())
                                    .arg(*cycles.rbegin());
        return result;
    }
    if (cycles.size() < 2)
        result.warnings << prefix + QStringLiteral("only cycle 0: every drift is zero");
    for (const TargetGroup& group : groupByTarget(run, settings.target_tolerance_mm))
        for (Direction d : {Direction::Positive, Direction::Negative}) {
            auto t = targetDrift(group, d, settings, &why);
            if (!why.isEmpty()) {
                result.error = prefix + why;
                result.targets.clear();
                return result;
            }
            if (t) result.targets.push_back(std::move(*t));
        }
    result.zero_mm = result.targets.front().target_mm;
    result.far_end_mm = result.targets.back().target_mm;
    for (std::size_t i = 0; i < result.targets.size(); ++i)
        if (result.max_index < 0 ||
            std::abs(result.targets[i].drift.max_drift_um) > std::abs(result.max_drift_um)) {
            result.max_index = int(i);
            result.max_drift_um = result.targets[i].drift.max_drift_um;
        }
    result.stabilised_time_s = latestStabilisation(
        result.targets, [](const TargetDrift& t) -> const DriftSeries& { return t.drift; });
    return result;
}

}  // namespace driftlab::iso
