#include "core/compensation/LinuxCncExport.h"

#include "core/compensation/FormatOptions.h"

namespace driftlab::compensation {

ExportResult exportLinuxCnc(const CompensationTable& table, LinuxCncType type) {
    ExportResult result;
    // The file type fixes the sign: type 0 holds nominal + error, type 1 the
    // correction; an explicit other sign is refused, never silently flipped.
    result.error = checkFormatOptions(
        type == LinuxCncType::Type0 ? QStringLiteral("linuxcnc") : QStringLiteral("linuxcnc-type1"),
        table.sign, table.values, false);
    if (!result.ok()) return result;
    if (table.size() > std::size_t(kLinuxCncMaxRows)) {
        result.error = QStringLiteral(
                           "LinuxCNC takes at most %1 compensation rows per joint; "
                           "this table has %2 points: use a larger spacing")
                           .arg(kLinuxCncMaxRows)
                           .arg(table.size());
        return result;
    }
    const double reversal_um =
        table.bidirectional || !std::isfinite(table.mean_reversal_um) ? 0 : table.mean_reversal_um;
    QByteArray previousNominal;
    for (std::size_t i = 0; i < table.size(); ++i) {
        const double nominal_mm = table.position_mm[i];
        // x̄↑ = x̄ + B̄/2 and x̄↓ = x̄ − B̄/2, so −x̄↑ = correction − B̄/2.
        const double trimPlus_mm = (table.correction_plus_um[i] - reversal_um / 2) / 1000;
        const double trimMinus_mm = (table.correction_minus_um[i] + reversal_um / 2) / 1000;
        const QByteArray nominal = fixed(nominal_mm, 4);
        // Two points that print alike would break LinuxCNC's strictly
        // increasing nominal ("compensation values must increase").
        if (i > 0 && nominal.toDouble() <= previousNominal.toDouble()) {
            result.error = QStringLiteral(
                               "points %1 and %2 both print as nominal %3 mm: LinuxCNC "
                               "needs strictly increasing nominals 0.0001 mm apart")
                               .arg(i - 1)
                               .arg(i)
                               .arg(QString::fromLatin1(nominal));
            return result;
        }
        previousNominal = nominal;
        // Type 0 stores the actual position: LinuxCNC's trim = nominal −
        // actual, so actual = nominal − trim (= nominal + deviation).
        const double second = type == LinuxCncType::Type0 ? nominal_mm - trimPlus_mm : trimPlus_mm;
        const double third = type == LinuxCncType::Type0 ? nominal_mm - trimMinus_mm : trimMinus_mm;
        result.text += nominal + ' ' + fixed(second, 4) + ' ' + fixed(third, 4) + '\n';
    }
    return result;
}

}  // namespace driftlab::compensation
