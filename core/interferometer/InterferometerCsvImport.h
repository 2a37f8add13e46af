#pragma once
// Import of an interferometer software's CSV export in DriftLab's generic
// column layout (docs/interferometer.md): one header row naming the columns
// (any order, extra columns ignored), then one row per reading:
//
//   time_s, position_mm, deviation_um           required
//   air_C, pressure_Pa, humidity_pct            the air, all three or none;
//                                               an empty cell: the air of the row before
//   material_C                                  optional, carried only
//
// A column is also found capitalised and with its unit in brackets ("Air [°C]",
// "Humidity [%]": core/bundle/ColumnSpelling.h). A vendor export that names
// its columns otherwise is read through a ColumnMapping (the user's choice of
// column per quantity); one that scales them otherwise must be converted. Whether the
// interferometer compensated itself is not in the file (no export states it
// the same way): the caller says it, as in the stream's header. Rows go
// through the stream's parser, so the same checks apply, and an error names
// the file, line and column.

#include <QString>
#include <optional>
#include <vector>

#include "core/bundle/BundleError.h"
#include "core/interferometer/InterferometerColumns.h"
#include "core/interferometer/InterferometerSession.h"

namespace driftlab::interferometer {

struct InterferometerCsvImport {
    std::vector<CorrectedReading> readings;    ///< `line` is the CSV line
    QString correction;                        ///< the last correction's description
    std::optional<bundle::BundleError> error;  ///< the first bad row; readings before are kept
};

InterferometerCsvImport importInterferometerCsv(const QString& path,
                                                const InterferometerHeader& header,
                                                double maxEnvironmentAge_s = 300.0);
/// The same with the file's own column names mapped onto the layout's.
InterferometerCsvImport importInterferometerCsv(const QString& path,
                                                const InterferometerHeader& header,
                                                const ColumnMapping& mapping,
                                                double maxEnvironmentAge_s = 300.0);

}  // namespace driftlab::interferometer
