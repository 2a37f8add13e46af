#pragma once
// Fanuc pitch error compensation data (parameters 3620–3624, incremental
// values per compensation point) as a `%` parameter file and as a G10 L50
// programme (docs/compensation.md, "Fanuc").

#include <cmath>
#include <limits>

#include "core/compensation/CompensationTable.h"
#include "core/compensation/ExportResult.h"

namespace driftlab::compensation {

struct FanucSettings {
    int axis = 1;                  ///< controlled axis number: the A of N03620A1P…
    double detection_unit_um = 1;  ///< 1 µm for IS-B metric axes
    int magnification = 1;         ///< parameter 3623: data × magnification = detection units
    /// Largest |value| per point in data units (the value after division by
    /// the magnification): ±7 on older series; 30i takes far more.
    int max_value_per_point = 7;
    /// Highest compensation point number of the control (0–1023 on 30i/0i-F).
    int max_point_number = 1023;
    /// Where the axis references; a table point. NaN: the point nearest 0 mm.
    double reference_mm = std::numeric_limits<double>::quiet_NaN();
    /// Parameter 3620: the number of the reference point. −1: chosen so that
    /// the first point is number 0.
    int reference_number = -1;
    int programme_number = 1000;  ///< the O-number of the G10 L50 programme

    bool isValid(QString* why) const;
};

/// The parameters and data a Fanuc control needs for the table, in detection
/// units; what both files are written from.
struct FanucPitchData {
    int reference_number = 0;  ///< 3620
    int most_negative = 0;     ///< 3621
    int most_positive = 0;     ///< 3622
    int magnification = 1;     ///< 3623
    long interval_units = 0;   ///< 3624, in detection units
    /// Parameter 1851 (backlash, detection units) from −B̄; absent when B̄ is not known.
    std::optional<long> backlash_units;
    std::vector<int> values;  ///< values[k] is point number most_negative + k
};

/// Incremental data: the value at point number n is the change of correction
/// over the interval that ends at n, in detection units / magnification,
/// rounded so that the rounding errors do not add up along the axis.
/// Refused: a bidirectional table, a value beyond the per-point limit (named),
/// point numbers beyond the control's range, a spacing that is not a whole
/// number of detection units.
std::optional<FanucPitchData> fanucPitchData(const CompensationTable& table,
                                             const FanucSettings& settings, ExportResult& result);

/// `%`, N0xxxxAaPv parameter lines (1851, 3620–3624), N1nnnnPv pitch data, `%`.
ExportResult exportFanucParameters(const CompensationTable& table, const FanucSettings& settings);
/// `%`, O-number, G10 L50, N1nnnn Rv per point, G11, M30, `%`.
ExportResult exportFanucG10(const CompensationTable& table, const FanucSettings& settings);

}  // namespace driftlab::compensation
