#pragma once
// Reads back a table that is active on a controller, from the controller's
// own file or from DriftLab's CSV, so that a residual measured with it
// switched on can be added to it (Recompensation.h, docs/compensation.md).

#include <QByteArray>
#include <QString>
#include <optional>

#include "core/compensation/CompensationTable.h"

namespace driftlab::compensation {

struct ActiveTableRead {
    QString error;  ///< empty on success; names the file, the line and why
    /// The table in corrections (µm), whatever sign the file holds; both
    /// columns as the file gives them (bidirectional when they differ).
    CompensationTable table;
    QString layout;  ///< what was read, e.g. "LinuxCNC COMP_FILE_TYPE 0"
    bool ok() const { return error.isEmpty(); }
};

/// `text` read from `where` (a file name, for messages). DriftLab's CSV is
/// recognised by its header (position_mm,...: any sign, absolute or
/// incremental); anything else is read as `format`'s own file: linuxcnc
/// (type 0), linuxcnc-type1, sinumerik, heidenhain (whose values carry
/// `sign`, unset: the format's own). Fanuc pitch data are increments that do
/// not hold the value at the reference point, so a Fanuc table is refused:
/// give it as CSV.
ActiveTableRead readActiveTable(const QByteArray& text, const QString& format,
                                std::optional<ValueSign> sign, const QString& where);

}  // namespace driftlab::compensation
