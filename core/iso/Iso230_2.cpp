#include "core/iso/Iso230_2.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "core/domain/MessageText.h"

namespace driftlab::iso {

std::optional<Edition> editionFromString(const QString& text) {
    const QString year = text.trimmed();
    if (year == QLatin1String("2014")) return Edition::Iso2014;
    if (year == QLatin1String("2006")) return Edition::Iso2006;
    if (year == QLatin1String("1997")) return Edition::Iso1997;
    return std::nullopt;
}

int editionYear(Edition edition) {
    switch (edition) {
        case Edition::Iso2014:
            return 2014;
        case Edition::Iso2006:
            return 2006;
        case Edition::Iso1997:
            return 1997;
    }
    return 0;
}

QString toString(Edition edition) {
    return QStringLiteral("ISO 230-2:%1").arg(editionYear(edition));
}

const std::vector<AxisValue>& axisValues() {
    static const std::vector<AxisValue> values{
        {"B", "B", "reversal error (max |B_i|)", &AxisResult::reversal_um},
        {"B_mean", "B̄", "mean reversal error", &AxisResult::mean_reversal_um},
        {"R_up", "R↑", "unidirectional repeatability ↑", &AxisResult::r_up_um},
        {"R_down", "R↓", "unidirectional repeatability ↓", &AxisResult::r_down_um},
        {"R", "R", "bidirectional repeatability", &AxisResult::r_um},
        {"E_up", "E↑", "unidirectional systematic error ↑", &AxisResult::e_up_um},
        {"E_down", "E↓", "unidirectional systematic error ↓", &AxisResult::e_down_um},
        {"E", "E", "bidirectional systematic error", &AxisResult::e_um},
        {"M", "M", "mean bidirectional positioning error", &AxisResult::m_um},
        {"A_up", "A↑", "unidirectional accuracy ↑", &AxisResult::a_up_um},
        {"A_down", "A↓", "unidirectional accuracy ↓", &AxisResult::a_down_um},
        {"A", "A", "bidirectional accuracy", &AxisResult::a_um}};
    return values;
}

double axisValue(const AxisResult& axis, const QString& key) {
    for (const AxisValue& v : axisValues())
        if (key == QLatin1String(v.key)) return axis.*v.value;
    return kNotDetermined;
}

std::vector<Reading> readingsOf(const Run& run) {
    std::vector<Reading> readings;
    readings.reserve(run.positioning.size());
    for (const PositioningMeasurement& m : run.positioning)
        readings.push_back({m.target_mm, m.direction, m.cycle, m.deviation_um});
    return readings;
}

bool Settings::isValid(QString* why) const {
    QString reason;
    if (!std::isfinite(coverage_factor) || coverage_factor <= 0)
        reason = QStringLiteral("coverage factor k must be a positive number, not %1")
                     .arg(coverage_factor);
    else if (!std::isfinite(long_axis_mm) || long_axis_mm <= 0)
        reason = QStringLiteral("long-axis length must be a positive number of mm");
    else if (!std::isfinite(target_tolerance_mm) || target_tolerance_mm < 0)
        reason = QStringLiteral("target tolerance must be a non-negative number of mm");
    if (why) *why = reason;
    return reason.isEmpty();
}

namespace {

/// The readings at one target, by direction.
struct Group {
    double target_mm = 0;
    std::vector<const Reading*> up, down;
    const std::vector<const Reading*>& of(Direction d) const {
        return d == Direction::Positive ? up : down;
    }
};

QString directionText(Direction d) {
    return d == Direction::Positive ? QStringLiteral("+ (↑)") : QStringLiteral("- (↓)");
}

/// Mean over the readings of one target and direction: the sum over its
/// cycles divided by how many readings there are (not by the number of targets).
double meanOf(const std::vector<const Reading*>& readings) {
    double sum = 0;
    for (const Reading* r : readings) sum += r->deviation_um;
    return sum / double(readings.size());
}

/// Sample standard deviation (n − 1), two-pass so that a large common offset
/// does not cancel digits; NaN below two readings.
double sampleSd(const std::vector<const Reading*>& readings, double mean) {
    if (readings.size() < 2) return kNotDetermined;
    double sum = 0;
    for (const Reading* r : readings) sum += (r->deviation_um - mean) * (r->deviation_um - mean);
    return std::sqrt(sum / double(readings.size() - 1));
}

/// Readings sorted by target, those within the tolerance merged into one target.
std::vector<Group> groupByTarget(const std::vector<Reading>& readings, double tolerance_mm) {
    std::vector<const Reading*> sorted;
    sorted.reserve(readings.size());
    for (const Reading& r : readings) sorted.push_back(&r);
    std::stable_sort(sorted.begin(), sorted.end(), [](const Reading* a, const Reading* b) {
        return a->target_mm < b->target_mm;
    });
    std::vector<Group> groups;
    for (const Reading* r : sorted) {
        if (groups.empty() || r->target_mm - groups.back().target_mm > tolerance_mm)
            groups.push_back({r->target_mm, {}, {}});
        (r->direction == Direction::Positive ? groups.back().up : groups.back().down).push_back(r);
    }
    return groups;
}

template <typename Value>
double maxOver(const std::vector<TargetResult>& targets, Value value) {
    double best = -std::numeric_limits<double>::infinity();
    for (const TargetResult& t : targets) best = std::max(best, value(t));
    return best;
}

template <typename Value>
double minOver(const std::vector<TargetResult>& targets, Value value) {
    double best = std::numeric_limits<double>::infinity();
    for (const TargetResult& t : targets) best = std::min(best, value(t));
    return best;
}

/// Non-stationary data inflate s and so R and A: a thermal drift from cycle to
/// cycle is not repeatability. The trend is fitted to the per-cycle mean of the
/// residuals (reading − its x̄ at that target and direction), so that the
/// targets' own systematic errors do not enter it.
std::optional<QString> driftWarning(const std::vector<Group>& groups,
                                    const std::vector<TargetResult>& targets) {
    std::map<int, std::pair<double, int>> perCycle;  // cycle → (sum of residuals, count)
    for (std::size_t i = 0; i < groups.size(); ++i)
        for (Direction d : {Direction::Positive, Direction::Negative}) {
            const double mean =
                d == Direction::Positive ? targets[i].mean_up_um : targets[i].mean_down_um;
            for (const Reading* r : groups[i].of(d)) {
                auto& [sum, count] = perCycle[r->cycle];
                sum += r->deviation_um - mean;
                ++count;
            }
        }
    if (perCycle.size() < 3) return std::nullopt;
    double cMean = 0, rMean = 0;
    for (const auto& [cycle, acc] : perCycle) {
        cMean += cycle;
        rMean += acc.first / acc.second;
    }
    cMean /= double(perCycle.size());
    rMean /= double(perCycle.size());
    double sxy = 0, sxx = 0;
    for (const auto& [cycle, acc] : perCycle) {
        sxy += (cycle - cMean) * (acc.first / acc.second - rMean);
        sxx += (cycle - cMean) * (cycle - cMean);
    }
    const double slope_um = sxy / sxx;
    // The span of the per-cycle means, not only the trend: a warm-up followed by
    // a cool-down rises and falls, and a straight line through it is flat.
    int lowCycle = perCycle.begin()->first, highCycle = lowCycle;
    double low_um = std::numeric_limits<double>::infinity(), high_um = -low_um;
    for (const auto& [cycle, acc] : perCycle) {
        const double mean_um = acc.first / acc.second;
        if (mean_um < low_um) low_um = mean_um, lowCycle = cycle;
        if (mean_um > high_um) high_um = mean_um, highCycle = cycle;
    }
    const double span_um = high_um - low_um;
    double sSum = 0;
    for (const TargetResult& t : targets) sSum += t.s_up_um + t.s_down_um;
    const double meanS_um = sSum / double(2 * targets.size());
    // A change below a nanometre is rounding, not drift (data with s = 0).
    if (span_um <= meanS_um || span_um < 1e-3) return std::nullopt;
    return QStringLiteral(
               "deviations drift from cycle to cycle: the per-cycle mean deviation spans %1 µm "
               "(lowest in cycle %2, highest in cycle %3; linear trend %4 µm per cycle), more "
               "than the mean standard deviation %5 µm; non-stationary data (e.g. thermal "
               "drift) inflate R and A")
        .arg(span_um, 0, 'f', 2)
        .arg(lowCycle)
        .arg(highCycle)
        .arg(slope_um, 0, 'f', 3)
        .arg(meanS_um, 0, 'f', 2);
}

QStringList repeatedReadings(const std::vector<Group>& groups) {
    QStringList warnings;
    for (const Group& g : groups)
        for (Direction d : {Direction::Positive, Direction::Negative}) {
            std::map<int, int> perCycle;
            for (const Reading* r : g.of(d)) ++perCycle[r->cycle];
            for (const auto& [cycle, count] : perCycle)
                if (count > 1)
                    warnings << QStringLiteral(
                                    "target %1 mm, direction %2, cycle %3: %4 readings; each is "
                                    "counted as an approach of its own")
                                    .arg(numberText(g.target_mm), directionText(d))
                                    .arg(cycle)
                                    .arg(count);
        }
    return warnings;
}

/// Why the s-based values cannot be determined, or an empty string when they can.
/// Sets `error` when the data cannot be evaluated at all.
QString checkCounts(const std::vector<Group>& groups, const Settings& settings, QString* error) {
    for (const Group& g : groups)
        for (Direction d : {Direction::Positive, Direction::Negative})
            if (g.of(d).empty()) {
                *error = QStringLiteral(
                             "target %1 mm, direction %2: no reading; ISO 230-2 needs both "
                             "approaches at every target")
                             .arg(numberText(g.target_mm), directionText(d));
                return {};
            }
    const double travel_mm = groups.back().target_mm - groups.front().target_mm;
    for (const Group& g : groups)
        for (Direction d : {Direction::Positive, Direction::Negative}) {
            if (g.of(d).size() >= 2) continue;
            const QString where = QStringLiteral("target %1 mm, direction %2")
                                      .arg(numberText(g.target_mm), directionText(d));
            const QString rule = QStringLiteral(
                                     "ISO 230-2 allows one approach per direction only on axes "
                                     "over %1 mm; this travel is %2 mm")
                                     .arg(numberText(settings.long_axis_mm), numberText(travel_mm));
            if (travel_mm <= settings.long_axis_mm) {
                *error =
                    where +
                    QStringLiteral(": 1 reading, the standard deviation s needs at least 2 (") +
                    rule + QLatin1Char(')');
                return {};
            }
            return QStringLiteral(
                       "s↑_i, s↓_i, R↑_i, R↓_i, R_i, R↑, R↓, R, A↑, A↓, A not "
                       "determined: ") +
                   where + QStringLiteral(" has one reading (") + rule + QLatin1Char(')');
        }
    return {};
}

/// Where the readings fall short of what ISO 230-2 asks for (at least five
/// targets, five per metre of travel, five approaches per direction at each
/// target on an axis up to the long-axis length). The values are still
/// determined, but the result is not an ISO 230-2 test: each is a warning.
QStringList belowMinimums(const std::vector<Group>& groups, const Settings& settings) {
    QStringList below;
    const QString prefix = QStringLiteral("below ISO 230-2's minimum: ");
    const double travel_mm = groups.back().target_mm - groups.front().target_mm;
    const auto needed = std::max(5, int(std::ceil(5 * travel_mm / 1000.0 - 1e-9)));
    if (int(groups.size()) < needed)
        below << prefix + QStringLiteral(
                              "%1 targets over %2 mm; at least %3 are needed (five, "
                              "and five per metre)")
                              .arg(groups.size())
                              .arg(numberText(travel_mm))
                              .arg(needed);
    if (travel_mm > settings.long_axis_mm) return below;
    std::size_t fewest = std::numeric_limits<std::size_t>::max();
    double at_mm = 0;
    Direction direction = Direction::Positive;
    for (const Group& g : groups)
        for (Direction d : {Direction::Positive, Direction::Negative})
            if (g.of(d).size() < fewest) {
                fewest = g.of(d).size();
                at_mm = g.target_mm;
                direction = d;
            }
    if (fewest < 5)
        below << prefix + QStringLiteral(
                              "%1 approaches at target %2 mm, direction %3; five "
                              "per direction at every target are needed")
                              .arg(fewest)
                              .arg(numberText(at_mm), directionText(direction));
    return below;
}

}  // namespace

Evaluation evaluate(const std::vector<Reading>& readings, const Settings& settings) {
    Evaluation result;
    result.settings = settings;
    if (!settings.isValid(&result.error)) return result;
    if (readings.empty()) {
        result.error = QStringLiteral("no readings to evaluate");
        return result;
    }
    for (std::size_t i = 0; i < readings.size(); ++i) {
        const Reading& r = readings[i];
        if (!std::isfinite(r.target_mm) || !std::isfinite(r.deviation_um)) {
            result.error =
                QStringLiteral("reading %1: target or deviation is not a finite number").arg(i + 1);
            return result;
        }
        if (std::abs(r.target_mm) > kMaxTarget_mm) {
            result.error = QStringLiteral(
                               "reading %1: target %2 mm is beyond any machine's travel "
                               "(±%3 mm)")
                               .arg(i + 1)
                               .arg(numberText(r.target_mm), numberText(kMaxTarget_mm));
            return result;
        }
        if (r.cycle < 0) {
            result.error = QStringLiteral("reading %1: cycle %2 is not a cycle number (0 or more)")
                               .arg(i + 1)
                               .arg(r.cycle);
            return result;
        }
    }
    const std::vector<Group> groups = groupByTarget(readings, settings.target_tolerance_mm);
    if (groups.size() < 2) {
        result.error = QStringLiteral(
                           "one target (%1 mm): E, M and A compare targets, so at "
                           "least 2 are needed; ISO 230-2 asks for at least 5")
                           .arg(numberText(groups.front().target_mm));
        return result;
    }
    const QString skipped = checkCounts(groups, settings, &result.error);
    if (!result.ok()) return result;
    result.warnings << belowMinimums(groups, settings);
    const bool withS = skipped.isEmpty();
    if (!withS) result.skipped << skipped;

    const double k = settings.coverage_factor;
    for (const Group& g : groups) {
        TargetResult t;
        t.target_mm = g.target_mm;
        t.n_up = int(g.up.size());
        t.n_down = int(g.down.size());
        t.mean_up_um = meanOf(g.up);
        t.mean_down_um = meanOf(g.down);
        t.mean_um = (t.mean_up_um + t.mean_down_um) / 2;
        t.reversal_um = t.mean_up_um - t.mean_down_um;
        if (withS) {
            t.s_up_um = sampleSd(g.up, t.mean_up_um);
            t.s_down_um = sampleSd(g.down, t.mean_down_um);
            t.r_up_um = 2 * k * t.s_up_um;
            t.r_down_um = 2 * k * t.s_down_um;
            // The bidirectional term spans both spreads and the gap between
            // the means; it can exceed either unidirectional R.
            t.r_um = std::max({k * t.s_up_um + k * t.s_down_um + std::abs(t.reversal_um), t.r_up_um,
                               t.r_down_um});
        }
        result.targets.push_back(t);
    }

    const auto& targets = result.targets;
    AxisResult& axis = result.axis;
    // B = max |B_i|, a magnitude as the standard defines it; B̄ keeps the signs.
    axis.reversal_um = 0;
    double reversalSum = 0;
    for (const TargetResult& t : targets) {
        axis.reversal_um = std::max(axis.reversal_um, std::abs(t.reversal_um));
        reversalSum += t.reversal_um;
    }
    axis.mean_reversal_um = reversalSum / double(targets.size());
    const auto up = [](const TargetResult& t) { return t.mean_up_um; };
    const auto down = [](const TargetResult& t) { return t.mean_down_um; };
    axis.e_up_um = maxOver(targets, up) - minOver(targets, up);
    axis.e_down_um = maxOver(targets, down) - minOver(targets, down);
    // E: the largest of all means minus the smallest of all, whichever
    // direction each comes from; it can exceed both E↑ and E↓.
    axis.e_um = std::max(maxOver(targets, up), maxOver(targets, down)) -
                std::min(minOver(targets, up), minOver(targets, down));
    const auto bidirectional = [](const TargetResult& t) { return t.mean_um; };
    axis.m_um = maxOver(targets, bidirectional) - minOver(targets, bidirectional);
    if (withS) {
        axis.r_up_um = maxOver(targets, [](const TargetResult& t) { return t.r_up_um; });
        axis.r_down_um = maxOver(targets, [](const TargetResult& t) { return t.r_down_um; });
        axis.r_um = maxOver(targets, [](const TargetResult& t) { return t.r_um; });
        const auto upHigh = [k](const TargetResult& t) { return t.mean_up_um + k * t.s_up_um; };
        const auto upLow = [k](const TargetResult& t) { return t.mean_up_um - k * t.s_up_um; };
        const auto downHigh = [k](const TargetResult& t) {
            return t.mean_down_um + k * t.s_down_um;
        };
        const auto downLow = [k](const TargetResult& t) {
            return t.mean_down_um - k * t.s_down_um;
        };
        axis.a_up_um = maxOver(targets, upHigh) - minOver(targets, upLow);
        axis.a_down_um = maxOver(targets, downHigh) - minOver(targets, downLow);
        axis.a_um = std::max(maxOver(targets, upHigh), maxOver(targets, downHigh)) -
                    std::min(minOver(targets, upLow), minOver(targets, downLow));
    }

    std::set<int> cycles;
    for (const Reading& r : readings) cycles.insert(r.cycle);
    result.cycles = int(cycles.size());
    result.warnings << repeatedReadings(groups);
    if (withS)
        if (auto warning = driftWarning(groups, targets)) result.warnings << *warning;
    return result;
}

}  // namespace driftlab::iso
