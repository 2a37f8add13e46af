#pragma once
// Re-compensation: a table that was active on the controller while the axis
// was measured again leaves a residual error; the new table is the active
// one plus the residual's correction (docs/compensation.md).

#include <QStringList>
#include <vector>

#include "core/compensation/CompensationTable.h"

namespace driftlab::compensation {

/// One point of the new table against the active one (corrections, µm).
struct PointChange {
    double position_mm = 0;
    double old_plus_um = 0, old_minus_um = 0;  ///< the active table at the point
    double new_plus_um = 0, new_minus_um = 0;
    double changePlusUm() const { return new_plus_um - old_plus_um; }
    double changeMinusUm() const { return new_minus_um - old_minus_um; }
};

struct RecompensationResult {
    QString error;  ///< empty on success; names the point and value at fault
    CompensationTable table;
    std::vector<PointChange> changes;  ///< one per point of `table`
    QStringList warnings;
    bool ok() const { return error.isEmpty(); }
};

/// `residual` is the table built, without limits, from the run measured
/// with `active` switched on. At each of its points the active table is
/// interpolated linearly (its end values held beyond its range, as the
/// controllers do) and the residual's correction added, per column. A
/// unidirectional result holds the mean of the active columns, and its B̄ is
/// the residual's plus the reversal the active columns folded in (their
/// mean difference − minus +). The result is checked against `limits`
/// (max value, max step) and `max_points`.
RecompensationResult recompensate(const CompensationTable& active,
                                  const CompensationTable& residual, const Limits& limits,
                                  int max_points);

}  // namespace driftlab::compensation
