#pragma once
// Heidenhain TNC / MANUALplus nonlinear axis error compensation table (.COM):
// one row per compensation point with the axis position, the value and a
// BACKLASH column (docs/compensation.md, "Heidenhain": the public
// documentation is thin; the layout is our reading of it).

#include "core/compensation/CompensationTable.h"
#include "core/compensation/ExportResult.h"

namespace driftlab::compensation {

/// A .COM table takes at most 256 entries (TNC module 9095 error 3).
constexpr int kHeidenhainMaxRows = 256;

struct HeidenhainSettings {
    QString axis = QStringLiteral("X");  ///< the column name: the axis key of CfgAxes/axisList
    QString table_name = QStringLiteral("X.COM");
};

/// `BEGIN name MM`, a column header `NR AXISPOS <axis> BACKLASH`, one row per
/// point (mm, 4 decimals, explicit sign), `[END]`. The axis column holds the
/// correction (with table.sign Error: the deviation); BACKLASH holds, in a bidirectional table, the
/// − column minus the + column, and 0 in a unidirectional one (the control's backlash parameter
/// takes B̄).
ExportResult exportHeidenhain(const CompensationTable& table, const HeidenhainSettings& settings);

}  // namespace driftlab::compensation
