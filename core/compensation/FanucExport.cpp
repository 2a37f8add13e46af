#include "core/compensation/FanucExport.h"

#include "core/compensation/FormatOptions.h"

namespace driftlab::compensation {
namespace {

/// Pitch error data numbers are 10000 + the compensation point number, in
/// parameter files and in G10 L50 alike.
constexpr int kPitchDataBase = 10000;

QByteArray parameterLine(int number, int axis, long value) {
    return 'N' + QByteArray::number(number).rightJustified(5, '0') + 'A' +
           QByteArray::number(axis) + 'P' + QByteArray::number(value) + '\n';
}

}  // namespace

bool FanucSettings::isValid(QString* why) const {
    QString reason;
    if (axis < 1) reason = QStringLiteral("the Fanuc axis number starts at 1, not %1").arg(axis);
    if (!(detection_unit_um > 0))
        reason = QStringLiteral("the detection unit must be a positive number of µm");
    if (magnification < 1)
        reason = QStringLiteral("the magnification (parameter 3623) must be at least 1");
    if (max_value_per_point < 1)
        reason = QStringLiteral("the per-point limit must be at least 1 data unit");
    if (why) *why = reason;
    return reason.isEmpty();
}

std::optional<FanucPitchData> fanucPitchData(const CompensationTable& table,
                                             const FanucSettings& settings, ExportResult& result) {
    QString why;
    if (!settings.isValid(&why)) {
        result.error = why;
        return std::nullopt;
    }
    result.error = checkFormatOptions(QStringLiteral("fanuc"), table.sign, table.values, false);
    if (!result.ok()) return std::nullopt;
    if (table.bidirectional) {
        // Bidirectional pitch error compensation (3605#0, 3626, 3627) is an
        // option with its own data layout, not written yet.
        result.error = QStringLiteral(
            "Fanuc export takes a unidirectional table: its backlash "
            "goes to parameter 1851 (bidirectional data, 3605#0/3626/"
            "3627, is not exported yet)");
        return std::nullopt;
    }
    const std::size_t n = table.size();
    const double unit_um = settings.detection_unit_um;
    const double interval = table.spacing_mm() * 1000 / unit_um;
    FanucPitchData data;
    data.magnification = settings.magnification;
    data.interval_units = std::lround(interval);
    if (std::abs(interval - double(data.interval_units)) > 1e-6) {
        result.error = QStringLiteral(
                           "the spacing %1 mm is not a whole number of %2 µm detection "
                           "units (parameter 3624)")
                           .arg(table.spacing_mm(), 0, 'f', 6)
                           .arg(unit_um);
        return std::nullopt;
    }
    // The reference point: given, or the table point nearest machine zero.
    std::size_t r = 0;
    if (std::isfinite(settings.reference_mm)) {
        const double at = (settings.reference_mm - table.position_mm.front()) / table.spacing_mm();
        if (at < -1e-6 || at > double(n - 1) + 1e-6 || std::abs(at - std::round(at)) > 1e-6) {
            result.error = QStringLiteral(
                               "the reference position %1 mm is not a point of the "
                               "table (%2 to %3 mm every %4 mm)")
                               .arg(settings.reference_mm, 0, 'f', 3)
                               .arg(table.position_mm.front(), 0, 'f', 3)
                               .arg(table.position_mm.back(), 0, 'f', 3)
                               .arg(table.spacing_mm(), 0, 'f', 3);
            return std::nullopt;
        }
        r = std::size_t(std::lround(at));
    } else {
        for (std::size_t i = 1; i < n; ++i)
            if (std::abs(table.position_mm[i]) < std::abs(table.position_mm[r])) r = i;
    }
    data.reference_number = settings.reference_number >= 0 ? settings.reference_number : int(r);
    // Point i has number reference_number + (i − r). The value at number k
    // covers the interval from point k−1 to point k, so the first table
    // point carries no value: 3621 = 3620 − (x_ref − x_0)/interval + 1.
    data.most_negative = data.reference_number - int(r) + 1;
    data.most_positive = data.reference_number + int(n - 1 - r);
    if (data.most_negative < 0 || data.most_positive > settings.max_point_number) {
        result.error = QStringLiteral(
                           "the table needs compensation point numbers %1 to %2, "
                           "beyond the control's 0 to %3: change the reference "
                           "number (3620) or use fewer points")
                           .arg(data.most_negative)
                           .arg(data.most_positive)
                           .arg(settings.max_point_number);
        return std::nullopt;
    }
    const double dataUnit_um = unit_um * settings.magnification;
    // Absolute corrections rounded first, increments taken after: the sum of
    // the increments then equals the rounded absolute correction everywhere.
    long previous = std::lround(table.meanCorrectionUm(0) / dataUnit_um);
    for (std::size_t i = 1; i < n; ++i) {
        const long absolute = std::lround(table.meanCorrectionUm(i) / dataUnit_um);
        const long value = absolute - previous;
        previous = absolute;
        const int number = data.most_negative + int(i) - 1;
        if (std::abs(value) > settings.max_value_per_point) {
            result.error = QStringLiteral(
                               "Fanuc point number %1 (%2 to %3 mm): increment %4 × "
                               "%5 µm exceeds the per-point limit ±%6 (magnification "
                               "%7): use a finer spacing or a larger magnification")
                               .arg(number)
                               .arg(table.position_mm[i - 1], 0, 'f', 3)
                               .arg(table.position_mm[i], 0, 'f', 3)
                               .arg(value)
                               .arg(dataUnit_um)
                               .arg(settings.max_value_per_point)
                               .arg(settings.magnification);
            return std::nullopt;
        }
        data.values.push_back(int(value));
    }
    const double atReference_um = table.meanCorrectionUm(r);
    if (std::abs(atReference_um) >= unit_um / 2)
        result.warnings << QStringLiteral(
                               "the correction at the reference point (%1 mm) is %2 "
                               "µm: incremental pitch data start from zero there, so "
                               "that offset stays with the reference position")
                               .arg(table.position_mm[r], 0, 'f', 3)
                               .arg(atReference_um, 0, 'f', 3);
    // Fanuc's backlash (1851) is the lost motion added on reversal: −B̄.
    if (std::isfinite(table.mean_reversal_um))
        data.backlash_units = std::lround(-table.mean_reversal_um / unit_um);
    return data;
}

ExportResult exportFanucParameters(const CompensationTable& table, const FanucSettings& settings) {
    ExportResult result;
    const auto data = fanucPitchData(table, settings, result);
    if (!data) return result;
    QByteArray& text = result.text;
    text += "%\n";
    if (data->backlash_units) text += parameterLine(1851, settings.axis, *data->backlash_units);
    text += parameterLine(3620, settings.axis, data->reference_number);
    text += parameterLine(3621, settings.axis, data->most_negative);
    text += parameterLine(3622, settings.axis, data->most_positive);
    text += parameterLine(3623, settings.axis, data->magnification);
    text += parameterLine(3624, settings.axis, data->interval_units);
    for (std::size_t k = 0; k < data->values.size(); ++k)
        text += 'N' + QByteArray::number(kPitchDataBase + data->most_negative + int(k)) + 'P' +
                QByteArray::number(data->values[k]) + '\n';
    text += "%\n";
    return result;
}

ExportResult exportFanucG10(const CompensationTable& table, const FanucSettings& settings) {
    ExportResult result;
    const auto data = fanucPitchData(table, settings, result);
    if (!data) return result;
    QByteArray& text = result.text;
    text += "%\nO" + QByteArray::number(settings.programme_number).rightJustified(4, '0') + '\n';
    // G10 L50 writes the data only: the comment names the parameters the
    // data assume, which the control must already hold.
    text += "(PITCH ERROR DATA AXIS " + QByteArray::number(settings.axis) +
            " 3620=" + QByteArray::number(data->reference_number) +
            " 3621=" + QByteArray::number(data->most_negative) +
            " 3622=" + QByteArray::number(data->most_positive) +
            " 3623=" + QByteArray::number(data->magnification) +
            " 3624=" + QByteArray::number(data->interval_units) + ")\n";
    text += "G10 L50\n";
    for (std::size_t k = 0; k < data->values.size(); ++k)
        text += 'N' + QByteArray::number(kPitchDataBase + data->most_negative + int(k)) + " R" +
                QByteArray::number(data->values[k]) + '\n';
    text += "G11\nM30\n%\n";
    return result;
}

}  // namespace driftlab::compensation
