#pragma once
// The table as CSV for spreadsheets and scripts: position_mm,correction_um
// (and correction_minus_um for a bidirectional table).

#include "core/compensation/CompensationTable.h"
#include "core/compensation/ExportResult.h"

namespace driftlab::compensation {

/// Header row, then one row per point: position in mm (4 decimals), the
/// correction the controller adds in µm (3 decimals; −deviation). In a
/// bidirectional table correction_um is the + approach's.
ExportResult exportCsv(const CompensationTable& table);

}  // namespace driftlab::compensation
