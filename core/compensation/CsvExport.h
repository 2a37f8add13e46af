#pragma once
// The table as CSV for spreadsheets and scripts: position_mm, the value
// column(s) and the uncertainty, in the sign and mode the table asks for.

#include "core/compensation/CompensationTable.h"
#include "core/compensation/ExportResult.h"

namespace driftlab::compensation {

/// The value column's name without its unit: correction or error, with
/// "_increment" for incremental values (correction_increment).
QByteArray csvValueColumn(ValueSign sign, ValueMode mode);

/// Header row, then one row per point: position in mm (4 decimals), the
/// value in µm (3 decimals): by default the correction the controller adds
/// (−deviation, column correction_um); with table.sign Error the deviation
/// (error_um); with table.values Incremental the change from the previous
/// row, the first row's from 0 (correction_increment_um). A bidirectional
/// table adds the − approach's column (correction_minus_um); the expanded
/// uncertainty (absolute, µm) comes last.
ExportResult exportCsv(const CompensationTable& table);

}  // namespace driftlab::compensation
