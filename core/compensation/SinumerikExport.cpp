#include "core/compensation/SinumerikExport.h"

#include <QRegularExpression>

#include "core/compensation/FormatOptions.h"

namespace driftlab::compensation {

ExportResult exportSinumerik(const CompensationTable& table, const SinumerikSettings& settings) {
    ExportResult result;
    // The name goes into every line: anything but a plain identifier would
    // make the control refuse the file or, worse, address another variable.
    static const QRegularExpression identifier(QStringLiteral("^[A-Za-z_][A-Za-z0-9_]{0,31}$"));
    if (!identifier.match(settings.axis).hasMatch()) {
        result.error = QStringLiteral("'%1' is not a Sinumerik machine axis name (e.g. X1, AX1)")
                           .arg(settings.axis);
        return result;
    }
    result.error = checkFormatOptions(QStringLiteral("sinumerik"), table.sign, table.values, false);
    if (!result.ok()) return result;
    if (table.bidirectional) {
        result.error = QStringLiteral(
            "Sinumerik export takes a unidirectional table: the backlash "
            "goes to MD32450 $MA_BACKLASH (direction-dependent tables "
            "are not exported yet)");
        return result;
    }
    if (table.size() > std::size_t(settings.max_points)) {
        result.error = QStringLiteral(
                           "the table has %1 points, more than MD38000 "
                           "$MA_MM_ENC_COMP_MAX_POINTS = %2 allows")
                           .arg(table.size())
                           .arg(settings.max_points);
        return result;
    }
    const QByteArray index = QByteArray::number(settings.encoder);
    const QByteArray axis = settings.axis.toLatin1();
    QByteArray& text = result.text;
    text += "%_N_AX_EEC_INI\nCHANDATA(1)\n";
    for (std::size_t i = 0; i < table.size(); ++i)
        text += "$AA_ENC_COMP[" + index + ',' + QByteArray::number(qulonglong(i)) + ',' + axis +
                "]=" + fixed(-table.meanCorrectionUm(i) / 1000, 4) + '\n';
    text += "$AA_ENC_COMP_STEP[" + index + ',' + axis + "]=" + fixed(table.spacing_mm(), 4) + '\n';
    text += "$AA_ENC_COMP_MIN[" + index + ',' + axis + "]=" + fixed(table.position_mm.front(), 4) +
            '\n';
    text +=
        "$AA_ENC_COMP_MAX[" + index + ',' + axis + "]=" + fixed(table.position_mm.back(), 4) + '\n';
    text += "$AA_ENC_COMP_IS_MODULO[" + index + ',' + axis + "]=0\nM17\n";
    return result;
}

}  // namespace driftlab::compensation
