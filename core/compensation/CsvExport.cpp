#include "core/compensation/CsvExport.h"

namespace driftlab::compensation {

ExportResult exportCsv(const CompensationTable& table) {
    ExportResult result;
    QByteArray& text = result.text;
    text += table.bidirectional ? "position_mm,correction_um,correction_minus_um\n"
                                : "position_mm,correction_um\n";
    for (std::size_t i = 0; i < table.size(); ++i) {
        text += fixed(table.position_mm[i], 4) + ',';
        if (table.bidirectional)
            text += fixed(table.correction_plus_um[i], 3) + ',' +
                    fixed(table.correction_minus_um[i], 3) + '\n';
        else
            text += fixed(table.meanCorrectionUm(i), 3) + '\n';
    }
    return result;
}

}  // namespace driftlab::compensation
