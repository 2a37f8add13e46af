#include "core/compensation/TemperatureCompensationLine.h"

#include <QRegularExpression>
#include <cmath>

namespace driftlab::compensation {

ErrorLine fitErrorLine(const std::vector<double>& position_mm, const std::vector<double>& error_um,
                       double reference_mm) {
    ErrorLine line;
    line.reference_mm = reference_mm;
    if (position_mm.size() != error_um.size() || position_mm.size() < 2) {
        line.error = QStringLiteral("a line needs at least two points with an error each");
        return line;
    }
    if (!std::isfinite(reference_mm)) {
        line.error = QStringLiteral("the reference position is not a number");
        return line;
    }
    // Centred sums: positions in mm reach 1e3 while errors are µm, so the
    // normal equations are kept well conditioned.
    const auto n = double(position_mm.size());
    double mean_x = 0, mean_e = 0;
    for (std::size_t i = 0; i < position_mm.size(); ++i) {
        if (!std::isfinite(position_mm[i]) || !std::isfinite(error_um[i])) {
            line.error = QStringLiteral("point %1 is not a number").arg(i);
            return line;
        }
        mean_x += position_mm[i] / n;
        mean_e += error_um[i] / n;
    }
    double sxx = 0, sxe = 0;
    for (std::size_t i = 0; i < position_mm.size(); ++i) {
        sxx += (position_mm[i] - mean_x) * (position_mm[i] - mean_x);
        sxe += (position_mm[i] - mean_x) * (error_um[i] - mean_e);
    }
    if (!(sxx > 0)) {
        line.error = QStringLiteral("every point is at %1 mm: a slope needs two positions")
                         .arg(position_mm.front());
        return line;
    }
    const double slope_um_per_mm = sxe / sxx;
    line.slope_um_per_m = slope_um_per_mm * 1e3;
    line.offset_um = mean_e + slope_um_per_mm * (reference_mm - mean_x);
    double squares = 0;
    for (std::size_t i = 0; i < position_mm.size(); ++i) {
        const double left = error_um[i] - line.errorAt_um(position_mm[i]);
        squares += left * left;
        line.residual_peak_um = std::max(line.residual_peak_um, std::abs(left));
    }
    line.residual_rms_um = std::sqrt(squares / n);
    return line;
}

ExportResult exportSinumerikTemperatureLine(const ErrorLine& line, const QString& axis) {
    ExportResult result;
    static const QRegularExpression identifier(QStringLiteral("^[A-Za-z_][A-Za-z0-9_]{0,31}$"));
    if (!line.ok()) {
        result.error = line.error;
        return result;
    }
    if (!identifier.match(axis).hasMatch()) {
        result.error =
            QStringLiteral("'%1' is not a Sinumerik machine axis name (e.g. X1, AX1)").arg(axis);
        return result;
    }
    const QByteArray ax = axis.toLatin1();
    // As the EEC table, Sinumerik's temperature compensation value corrects
    // the actual value, so it holds the error (+deviation), in mm; the slope
    // is a gradient (mm per mm).
    QByteArray& text = result.text;
    text += "%_N_DRIFTLAB_TEMP_COMP_SPF\n;$PATH=/_N_SPF_DIR\n";
    text += "; DriftLab straight-line temperature compensation of " + ax + "\n";
    text += "; needs MD32750 $MA_TEMP_COMP_TYPE[" + ax +
            "]=3 (bit 0: SD43900, bit 1: SD43910/SD43920), set at commissioning\n";
    text += "; line residual " + fixed(line.residual_rms_um, 3) + " um RMS, " +
            fixed(line.residual_peak_um, 3) + " um peak\n";
    text += "$SA_TEMP_COMP_ABS_VALUE[" + ax + "]=" + fixed(line.offset_um / 1000, 4) + '\n';
    text += "$SA_TEMP_COMP_SLOPE[" + ax + "]=" + fixed(line.slope_um_per_m * 1e-6, 8) + '\n';
    text += "$SA_TEMP_COMP_REF_POSITION[" + ax + "]=" + fixed(line.reference_mm, 4) + '\n';
    text += "M17\n";
    return result;
}

ExportResult exportIsgTemperatureLine(const ErrorLine& line) {
    ExportResult result;
    if (!line.ok()) {
        result.error = line.error;
        return result;
    }
    // ISG corrects the commanded value: the parameters hold the correction
    // (−error). Positions and offsets are integers of 0.1 µm, the coefficient
    // an integer of µm/m (SGN32 in the parameter list).
    const double coefficient = -line.slope_um_per_m;
    const double rounding_um_per_m = std::abs(std::round(coefficient) - coefficient);
    QByteArray& text = result.text;
    text += "# DriftLab straight-line temperature compensation\n";
    text += "lr_param.temp_comp                  1\n";
    text += "lr_param.temp_comp_position_0       " +
            QByteArray::number(qlonglong(std::llround(line.reference_mm * 1e4))) + "\n";
    text += "lr_param.temp_comp_offset_0         " +
            QByteArray::number(qlonglong(std::llround(-line.offset_um * 10))) + "\n";
    text += "lr_param.temp_comp_coefficient      " +
            QByteArray::number(qlonglong(std::llround(coefficient))) + "\n";
    if (rounding_um_per_m >= 0.05)
        result.warnings << QStringLiteral(
                               "temp_comp_coefficient is whole µm/m: rounding it moves the "
                               "correction by %1 µm per metre from the reference")
                               .arg(rounding_um_per_m, 0, 'f', 2);
    return result;
}

}  // namespace driftlab::compensation
