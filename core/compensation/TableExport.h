#pragma once
// One entry point for every table format a controller takes, so that the CLI
// (`compensate --format`) and the GUI's Compensation page write the same bytes.

#include <QStringList>

#include "core/compensation/CompensationTable.h"
#include "core/compensation/ExportResult.h"

namespace driftlab::compensation {

/// linuxcnc, linuxcnc-type1, fanuc, fanuc-g10, sinumerik, heidenhain, csv.
QStringList tableFormats();

/// The few per-controller choices the formats take (the CLI's --axis and
/// --magnification).
struct TableExportSettings {
    /// Sinumerik machine axis name (default AX1), Heidenhain axis key
    /// (default: campaign_axis, else X) or Fanuc axis number (default 1);
    /// empty: the default.
    QString axis;
    QString campaign_axis;  ///< the campaign's axis name (Machine::axis), may be empty
    int magnification = 1;  ///< Fanuc parameter 3623
};

/// Empty when `format` is one of tableFormats() and `settings` suit it;
/// otherwise why not, naming the value ("axis: Fanuc takes ...").
QString checkTableExport(const QString& format, const TableExportSettings& settings);

/// The file text of `table` in `format` (checkTableExport() first).
ExportResult exportTable(const CompensationTable& table, const QString& format,
                         const TableExportSettings& settings);

}  // namespace driftlab::compensation
