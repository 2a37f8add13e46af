#include "core/compensation/CsvExport.h"

namespace driftlab::compensation {

ExportResult exportCsv(const CompensationTable& table) {
    ExportResult result;
    QByteArray& text = result.text;
    // The uncertainty column last, so that a reader of the first columns
    // reads the table as before.
    const bool uncertain = table.uncertainty_um.size() == table.size();
    text += table.bidirectional ? "position_mm,correction_um,correction_minus_um"
                                : "position_mm,correction_um";
    text += uncertain ? ",uncertainty_um\n" : "\n";
    for (std::size_t i = 0; i < table.size(); ++i) {
        text += fixed(table.position_mm[i], 4) + ',';
        if (table.bidirectional)
            text += fixed(table.correction_plus_um[i], 3) + ',' +
                    fixed(table.correction_minus_um[i], 3);
        else
            text += fixed(table.meanCorrectionUm(i), 3);
        text += uncertain ? ',' + fixed(table.uncertainty_um[i], 3) + '\n' : QByteArray("\n");
    }
    return result;
}

}  // namespace driftlab::compensation
