#pragma once
// The straight-line temperature compensation that controllers do natively:
// an offset at a reference position plus a slope versus position, fitted by
// least squares to a thermal error profile (e.g. a model's error at a stated
// state). A screw fixed at one end grows roughly linearly from it, so a line
// carries most of the thermal error; what it leaves is reported, never hidden.
//
//   Sinumerik: ΔK = SD43900 $SA_TEMP_COMP_ABS_VALUE
//                 + SD43910 $SA_TEMP_COMP_SLOPE · (position − SD43920 $SA_TEMP_COMP_REF_POSITION),
//              enabled by MD32750 $MA_TEMP_COMP_TYPE bits 0 and 1;
//   ISG / TwinCAT CNC: lr_param.temp_comp_position_0, temp_comp_offset_0 (0.1 µm),
//              temp_comp_coefficient (µm/m), enabled by lr_param.temp_comp.
// docs/compensation.md has the sign each controller takes.

#include <vector>

#include "core/compensation/ExportResult.h"

namespace driftlab::compensation {

/// error(x) ≈ offset_um + slope_um_per_m · (x − reference_mm)/1000, where
/// error is the deviation actual − target (ISO 230-2 sign).
struct ErrorLine {
    double reference_mm = 0;
    double offset_um = 0;
    double slope_um_per_m = 0;
    /// What the line leaves of the profile it was fitted to.
    double residual_rms_um = 0;
    double residual_peak_um = 0;
    QString error;  ///< empty on success
    bool ok() const { return error.isEmpty(); }

    double errorAt_um(double position_mm) const {
        return offset_um + slope_um_per_m * (position_mm - reference_mm) * 1e-3;
    }
};

/// Least-squares line through (position, error) pairs; at least two distinct
/// finite positions.
ErrorLine fitErrorLine(const std::vector<double>& position_mm, const std::vector<double>& error_um,
                       double reference_mm);

/// Sinumerik setting data for `axis` as a subprogram (`%_N_..._SPF`, M17).
ExportResult exportSinumerikTemperatureLine(const ErrorLine& line, const QString& axis);

/// ISG / TwinCAT CNC axis parameter lines.
ExportResult exportIsgTemperatureLine(const ErrorLine& line);

}  // namespace driftlab::compensation
