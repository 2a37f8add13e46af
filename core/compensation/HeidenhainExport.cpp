#include "core/compensation/HeidenhainExport.h"

#include <QRegularExpression>

#include "core/compensation/FormatOptions.h"

namespace driftlab::compensation {
namespace {

/// TNC tables are read by column position: every field is padded to its
/// header's width.
constexpr int kNumberWidth = 6;
constexpr int kValueWidth = 16;

}  // namespace

ExportResult exportHeidenhain(const CompensationTable& table, const HeidenhainSettings& settings) {
    ExportResult result;
    static const QRegularExpression axisKey(QStringLiteral("^[A-Za-z][A-Za-z0-9_]{0,14}$"));
    if (!axisKey.match(settings.axis).hasMatch()) {
        result.error =
            QStringLiteral("'%1' is not a Heidenhain axis key (e.g. X)").arg(settings.axis);
        return result;
    }
    result.error =
        checkFormatOptions(QStringLiteral("heidenhain"), table.sign, table.values, false);
    if (!result.ok()) return result;
    if (table.size() > std::size_t(kHeidenhainMaxRows)) {
        result.error = QStringLiteral(
                           "a Heidenhain .COM table takes at most %1 points; this table "
                           "has %2: use a larger spacing")
                           .arg(kHeidenhainMaxRows)
                           .arg(table.size());
        return result;
    }
    const ValueSign sign = table.sign.value_or(ValueSign::Correction);
    const std::vector<double> plus = table.writtenValuesUm(true, sign, ValueMode::Absolute);
    const std::vector<double> minus = table.writtenValuesUm(false, sign, ValueMode::Absolute);
    QByteArray& text = result.text;
    text += "BEGIN " + settings.table_name.toUpper().toLatin1() + " MM\n";
    text += QByteArray("NR").leftJustified(kNumberWidth) +
            QByteArray("AXISPOS").leftJustified(kValueWidth) +
            settings.axis.toUpper().toLatin1().leftJustified(kValueWidth) + "BACKLASH\n";
    for (std::size_t i = 0; i < table.size(); ++i) {
        const double value_mm = plus[i] / 1000;
        const double backlash_mm = table.bidirectional ? (minus[i] - plus[i]) / 1000 : 0.0;
        text += QByteArray::number(qulonglong(i)).leftJustified(kNumberWidth) +
                signedFixed(table.position_mm[i], 4).leftJustified(kValueWidth) +
                signedFixed(value_mm, 4).leftJustified(kValueWidth) + signedFixed(backlash_mm, 4) +
                '\n';
    }
    text += "[END]\n";
    return result;
}

}  // namespace driftlab::compensation
