#include "core/compensation/Recompensation.h"

#include <algorithm>
#include <cmath>

namespace driftlab::compensation {
namespace {

/// Per-point reversals of the active table that differ from their mean by
/// more than this are lost in a unidirectional table (a warning says so);
/// the files round to 0.1 µm, so a folded B̄ reads back that much apart.
constexpr double kReversalSpreadUm = 0.25;

/// `column` of `table` at `x`: linear between points, end values held.
double heldInterpolation(const CompensationTable& table, const std::vector<double>& column,
                         double x) {
    const std::vector<double>& p = table.position_mm;
    if (x <= p.front()) return column.front();
    if (x >= p.back()) return column.back();
    const auto upper = std::upper_bound(p.begin(), p.end(), x);
    const std::size_t b = std::size_t(upper - p.begin()), a = b - 1;
    const double f = (x - p[a]) / (p[b] - p[a]);
    return column[a] + f * (column[b] - column[a]);
}

double noNegativeZero(double value) {
    return value == 0 ? 0.0 : value;
}

}  // namespace

RecompensationResult recompensate(const CompensationTable& active,
                                  const CompensationTable& residual, const Limits& limits,
                                  int max_points) {
    RecompensationResult result;
    if (active.size() < 2 || residual.size() < 2) {
        result.error = QStringLiteral(
            "re-compensation needs an active table and a residual of "
            "2 points at least");
        return result;
    }
    CompensationTable& table = result.table;
    table = residual;
    table.correction_plus_um.clear();
    table.correction_minus_um.clear();
    double reversalSum = 0, reversalMin = INFINITY, reversalMax = -INFINITY;
    for (std::size_t i = 0; i < active.size(); ++i) {
        const double reversal = active.correction_minus_um[i] - active.correction_plus_um[i];
        reversalSum += reversal;
        reversalMin = std::min(reversalMin, reversal);
        reversalMax = std::max(reversalMax, reversal);
    }
    // trim+ = c − B̄/2 and trim− = c + B̄/2: the active columns' difference
    // is the reversal they compensate.
    const double activeReversal_um = reversalSum / double(active.size());
    for (std::size_t i = 0; i < residual.size(); ++i) {
        const double x = residual.position_mm[i];
        PointChange change;
        change.position_mm = x;
        change.old_plus_um = heldInterpolation(active, active.correction_plus_um, x);
        change.old_minus_um = heldInterpolation(active, active.correction_minus_um, x);
        if (!residual.bidirectional) {
            change.old_plus_um = change.old_minus_um =
                (change.old_plus_um + change.old_minus_um) / 2;
        }
        change.new_plus_um = noNegativeZero(change.old_plus_um + residual.correction_plus_um[i]);
        change.new_minus_um = noNegativeZero(change.old_minus_um + residual.correction_minus_um[i]);
        table.correction_plus_um.push_back(change.new_plus_um);
        table.correction_minus_um.push_back(change.new_minus_um);
        result.changes.push_back(change);
    }
    if (!residual.bidirectional) {
        const double residualReversal =
            std::isfinite(residual.mean_reversal_um) ? residual.mean_reversal_um : 0.0;
        table.mean_reversal_um = residualReversal + activeReversal_um;
        if (reversalMax - reversalMin > kReversalSpreadUm)
            result.warnings << QStringLiteral(
                                   "the active table's − and + columns differ by %1 to %2 µm "
                                   "along the axis: a unidirectional table keeps only their "
                                   "mean, %3 µm, in B̄ (--bidirectional keeps them per point)")
                                   .arg(reversalMin, 0, 'f', 3)
                                   .arg(reversalMax, 0, 'f', 3)
                                   .arg(activeReversal_um, 0, 'f', 3);
    }
    result.error = validate(table, limits, max_points);
    return result;
}

}  // namespace driftlab::compensation
