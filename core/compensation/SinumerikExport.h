#pragma once
// Sinumerik 840D sl / 828D / 808D leadscrew error compensation (LEC/EEC)
// table: an `%_N_AX_EEC_INI` file of $AA_ENC_COMP system variables
// (docs/compensation.md, "Sinumerik").

#include "core/compensation/CompensationTable.h"
#include "core/compensation/ExportResult.h"

namespace driftlab::compensation {

struct SinumerikSettings {
    QString axis = QStringLiteral("AX1");  ///< machine axis name, e.g. X1 or AX1
    int encoder = 0;                       ///< measuring system: 0 = first encoder
    /// MD38000 $MA_MM_ENC_COMP_MAX_POINTS of the axis: no more points than this.
    int max_points = 1000;
};

/// Values in mm, 4 decimals. Sinumerik corrects the actual value by the
/// table value ("a positive compensation value causes the machine axis to
/// move in the negative direction"), so the table holds +deviation =
/// −correction. A bidirectional table is refused (direction-dependent
/// compensation is a separate table type); the backlash B̄ belongs in
/// MD32450 $MA_BACKLASH.
ExportResult exportSinumerik(const CompensationTable& table, const SinumerikSettings& settings);

}  // namespace driftlab::compensation
