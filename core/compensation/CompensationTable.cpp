#include "core/compensation/CompensationTable.h"

#include "core/compensation/LeadAliasing.h"

#include <algorithm>
#include <cmath>

namespace driftlab::compensation {
namespace {

/// Positions this close are the same (a table end computed as start + n·step
/// lands a few ulp beyond the last target).
constexpr double kPositionToleranceMm = 1e-9;

QString mm(double value) {
    return QString::number(value, 'f', 3);
}

QString um(double value) {
    return QString::number(value, 'f', 3);
}

/// −0 prints as "-0.0000" in every format: a controller operator reads that
/// as a sign error, so a zero correction is always +0.
double withoutNegativeZero(double value) {
    return value == 0 ? 0.0 : value;
}

struct TargetDeviation {
    double target_mm;
    double plus_um;
    double minus_um;
    double uncertainty_um;  ///< expanded (k = 2) of the mean deviation
};

/// The expanded uncertainty of a target's mean deviation from its cycles'
/// scatter: 2·s/√n of each direction (the larger), or of their mean.
double meanDeviationUncertainty(const iso::TargetResult& t, bool bidirectional) {
    const double up = t.n_up > 1 ? t.s_up_um / std::sqrt(double(t.n_up)) : 0;
    const double down = t.n_down > 1 ? t.s_down_um / std::sqrt(double(t.n_down)) : 0;
    const double u = bidirectional ? std::max(up, down) : 0.5 * std::hypot(up, down);
    return std::isfinite(u) ? 2 * u : 0;
}

/// Linear interpolation of `column` over the targets at `x`, which lies
/// within their span.
double interpolate(const std::vector<TargetDeviation>& targets, double x,
                   double TargetDeviation::*column) {
    auto upper =
        std::upper_bound(targets.begin(), targets.end(), x,
                         [](double v, const TargetDeviation& t) { return v < t.target_mm; });
    if (upper == targets.begin()) return (*upper).*column;
    if (upper == targets.end()) return targets.back().*column;
    const TargetDeviation& a = *(upper - 1);
    const TargetDeviation& b = *upper;
    const double f = (x - a.target_mm) / (b.target_mm - a.target_mm);
    return a.*column + f * (b.*column - a.*column);
}

QString columnName(const CompensationTable& table, bool plus) {
    if (!table.bidirectional) return QString();
    return plus ? QStringLiteral(" (+ column)") : QStringLiteral(" (− column)");
}

}  // namespace

bool TableSettings::isValid(QString* why) const {
    QString reason;
    if (spacing_mm != 0 && points != 0)
        reason = QStringLiteral("give a spacing or a point count, not both");
    else if (spacing_mm < 0 || !std::isfinite(spacing_mm))
        reason = QStringLiteral("spacing must be a positive number of mm, not %1").arg(spacing_mm);
    else if (points != 0 && points < 2)
        reason = QStringLiteral("a table needs at least 2 points, not %1").arg(points);
    else if ((start_mm && !std::isfinite(*start_mm)) || (end_mm && !std::isfinite(*end_mm)))
        reason = QStringLiteral("start and end must be finite positions");
    else if (start_mm && end_mm && *start_mm >= *end_mm)
        reason =
            QStringLiteral("start %1 mm must lie below end %2 mm").arg(mm(*start_mm), mm(*end_mm));
    else if (screw_lead_mm < 0 || !std::isfinite(screw_lead_mm))
        reason = QStringLiteral("the screw lead must be a positive number of mm, or 0 (unknown)");
    else if (max_points < 2)
        reason = QStringLiteral("the maximum point count must be at least 2");
    if (why) *why = reason;
    return reason.isEmpty();
}

bool Limits::isValid(QString* why) const {
    QString reason;
    // NaN compares false with everything: a NaN limit would let any table pass.
    for (double limit : {max_value_um, max_step_um, max_change_um})
        if (std::isnan(limit) || limit <= 0)
            reason = QStringLiteral("limits must be positive numbers of µm, not %1").arg(limit);
    if (why) *why = reason;
    return reason.isEmpty();
}

double CompensationTable::maxAbsCorrectionUm() const {
    double peak = 0;
    for (std::size_t i = 0; i < size(); ++i)
        peak = std::max({peak, std::abs(correction_plus_um[i]), std::abs(correction_minus_um[i])});
    return peak;
}

std::vector<double> CompensationTable::writtenValuesUm(bool plus, ValueSign sign,
                                                       ValueMode mode) const {
    std::vector<double> values;
    double previous = 0;
    for (std::size_t i = 0; i < size(); ++i) {
        const double correction = bidirectional
                                      ? (plus ? correction_plus_um[i] : correction_minus_um[i])
                                      : meanCorrectionUm(i);
        const double value = signedValue(correction, sign);
        values.push_back(
            withoutNegativeZero(mode == ValueMode::Absolute ? value : value - previous));
        previous = value;
    }
    return values;
}

QString validate(const CompensationTable& table, const Limits& limits, int max_points) {
    const std::size_t n = table.size();
    if (n < 2) return QStringLiteral("a table needs at least 2 points, not %1").arg(n);
    if (n > std::size_t(max_points))
        return QStringLiteral("%1 points exceed the maximum of %2").arg(n).arg(max_points);
    if (table.correction_plus_um.size() != n || table.correction_minus_um.size() != n)
        return QStringLiteral("the correction columns do not have one value per point");
    for (std::size_t i = 0; i < n; ++i) {
        const double x = table.position_mm[i];
        if (!std::isfinite(x)) return QStringLiteral("point %1: position is not finite").arg(i);
        if (i > 0 && !(x > table.position_mm[i - 1]))
            return QStringLiteral(
                       "point %1 at %2 mm: positions must increase strictly "
                       "(point %3 is at %4 mm)")
                .arg(i)
                .arg(mm(x))
                .arg(i - 1)
                .arg(mm(table.position_mm[i - 1]));
        for (bool plus : {true, false}) {
            const auto& column = plus ? table.correction_plus_um : table.correction_minus_um;
            const double v = column[i];
            if (!std::isfinite(v))
                return QStringLiteral("point %1 at %2 mm: correction%3 is not a finite number")
                    .arg(i)
                    .arg(mm(x), columnName(table, plus));
            if (std::abs(v) > limits.max_value_um)
                return QStringLiteral(
                           "point %1 at %2 mm: correction%3 %4 µm exceeds the limit "
                           "±%5 µm (max value)")
                    .arg(i)
                    .arg(mm(x), columnName(table, plus), um(v), um(limits.max_value_um));
            if (i > 0 && std::abs(v - column[i - 1]) > limits.max_step_um)
                return QStringLiteral(
                           "point %1 at %2 mm: correction%3 steps from %4 µm to %5 µm "
                           "(%6 µm) against point %7, beyond the limit %8 µm between "
                           "neighbours (max step)")
                    .arg(i)
                    .arg(mm(x), columnName(table, plus), um(column[i - 1]), um(v),
                         um(v - column[i - 1]))
                    .arg(i - 1)
                    .arg(um(limits.max_step_um));
        }
    }
    return QString();
}

QString checkChange(const CompensationTable& previous, const CompensationTable& next,
                    const Limits& limits) {
    if (previous.size() != next.size())
        return QStringLiteral(
                   "the previous table has %1 points, the new one %2: a change is "
                   "checked point by point")
            .arg(previous.size())
            .arg(next.size());
    for (std::size_t i = 0; i < next.size(); ++i) {
        if (std::abs(previous.position_mm[i] - next.position_mm[i]) > kPositionToleranceMm)
            return QStringLiteral(
                       "point %1 is at %2 mm in the previous table and at %3 mm in the "
                       "new one")
                .arg(i)
                .arg(mm(previous.position_mm[i]), mm(next.position_mm[i]));
        for (bool plus : {true, false}) {
            const double before =
                plus ? previous.correction_plus_um[i] : previous.correction_minus_um[i];
            const double after = plus ? next.correction_plus_um[i] : next.correction_minus_um[i];
            if (std::abs(after - before) > limits.max_change_um)
                return QStringLiteral(
                           "point %1 at %2 mm: correction%3 changes from %4 µm to %5 "
                           "µm, beyond the limit %6 µm per update (max change)")
                    .arg(i)
                    .arg(mm(next.position_mm[i]), columnName(next, plus), um(before), um(after),
                         um(limits.max_change_um));
        }
    }
    return QString();
}

TableResult buildTable(const iso::Evaluation& evaluation, const TableSettings& settings,
                       const Limits& limits, const ErrorProfile& extra,
                       const ErrorProfile& extraUncertainty) {
    TableResult result;
    QString why;
    if (!settings.isValid(&why) || !limits.isValid(&why)) {
        result.error = why;
        return result;
    }
    if (!evaluation.ok()) {
        result.error = evaluation.error;
        return result;
    }
    if (evaluation.targets.size() < 2) {
        result.error = QStringLiteral("a table needs readings at two targets at least, not %1")
                           .arg(evaluation.targets.size());
        return result;
    }

    // The cold geometric error at each target: x̄↑ and x̄↓, or their mean x̄.
    // evaluate() already refused a target missing one direction.
    std::vector<TargetDeviation> targets;
    for (const iso::TargetResult& t : evaluation.targets)
        targets.push_back({t.target_mm, settings.bidirectional ? t.mean_up_um : t.mean_um,
                           settings.bidirectional ? t.mean_down_um : t.mean_um,
                           meanDeviationUncertainty(t, settings.bidirectional)});

    const double first = targets.front().target_mm, last = targets.back().target_mm;
    const double start = settings.start_mm.value_or(first);
    const double end = settings.end_mm.value_or(last);
    // Refused rather than clamped: a flat extension beyond the measured span
    // would look like a measured correction on the controller's screen.
    if (start < first - kPositionToleranceMm || end > last + kPositionToleranceMm) {
        result.error = QStringLiteral(
                           "the table range %1 to %2 mm reaches beyond the measured "
                           "targets %3 to %4 mm: a table is not extrapolated")
                           .arg(mm(start), mm(end), mm(first), mm(last));
        return result;
    }
    if (!(start < end)) {
        result.error =
            QStringLiteral("start %1 mm must lie below end %2 mm").arg(mm(start), mm(end));
        return result;
    }

    std::size_t count = 0;
    double spacing = 0;
    if (settings.spacing_mm > 0) {
        spacing = settings.spacing_mm;
        const double steps = std::floor((end - start) / spacing + 1e-9);
        if (steps + 1 > settings.max_points) {
            result.error = QStringLiteral(
                               "a spacing of %1 mm over %2 to %3 mm gives %4 points, "
                               "more than the maximum of %5")
                               .arg(mm(spacing), mm(start), mm(end))
                               .arg(steps + 1)
                               .arg(settings.max_points);
            return result;
        }
        count = std::size_t(steps) + 1;
        if (start + double(count - 1) * spacing < end - 1e-6)
            result.warnings << QStringLiteral(
                                   "the range %1 to %2 mm is not a whole number of "
                                   "%3 mm steps: the table ends at %4 mm")
                                   .arg(mm(start), mm(end), mm(spacing),
                                        mm(start + double(count - 1) * spacing));
    } else {
        count = settings.points > 0 ? std::size_t(settings.points) : targets.size();
        if (count > std::size_t(settings.max_points)) {
            result.error = QStringLiteral("%1 points exceed the maximum of %2")
                               .arg(count)
                               .arg(settings.max_points);
            return result;
        }
        spacing = (end - start) / double(count - 1);
    }
    if (count < 2) {
        result.error = QStringLiteral(
                           "a spacing of %1 mm leaves fewer than 2 points between %2 "
                           "and %3 mm")
                           .arg(mm(spacing), mm(start), mm(end));
        return result;
    }

    CompensationTable& table = result.table;
    table.bidirectional = settings.bidirectional;
    table.sign = settings.sign;
    table.values = settings.values;
    std::vector<double> measured_mm;
    for (const TargetDeviation& t : targets) measured_mm.push_back(t.target_mm);
    const QString aliasing = leadAliasingWarning(measured_mm, settings.screw_lead_mm);
    if (!aliasing.isEmpty()) result.warnings << aliasing;
    table.mean_reversal_um = evaluation.axis.mean_reversal_um;
    for (std::size_t i = 0; i < count; ++i) {
        // start + i·spacing, not a running sum: no drift over 1000 points.
        const double x = std::clamp(start + double(i) * spacing, first, last);
        const double added = extra ? extra(x) : 0.0;
        if (!std::isfinite(added)) {
            result.error = QStringLiteral(
                               "point %1 at %2 mm: the added error is not a finite "
                               "number")
                               .arg(i)
                               .arg(mm(x));
            return result;
        }
        table.position_mm.push_back(x);
        table.correction_plus_um.push_back(
            withoutNegativeZero(-(interpolate(targets, x, &TargetDeviation::plus_um) + added)));
        table.correction_minus_um.push_back(
            withoutNegativeZero(-(interpolate(targets, x, &TargetDeviation::minus_um) + added)));
        const double thermal = extraUncertainty ? extraUncertainty(x) : 0.0;
        table.uncertainty_um.push_back(
            std::hypot(interpolate(targets, x, &TargetDeviation::uncertainty_um),
                       std::isfinite(thermal) ? thermal : 0.0));
    }
    result.error = validate(table, limits, settings.max_points);
    return result;
}

}  // namespace driftlab::compensation
