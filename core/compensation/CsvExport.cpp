#include "core/compensation/CsvExport.h"

namespace driftlab::compensation {

QByteArray csvValueColumn(ValueSign sign, ValueMode mode) {
    QByteArray name = sign == ValueSign::Correction ? "correction" : "error";
    if (mode == ValueMode::Incremental) name += "_increment";
    return name;
}

ExportResult exportCsv(const CompensationTable& table) {
    ExportResult result;
    const ValueSign sign = table.sign.value_or(ValueSign::Correction);
    const ValueMode mode = table.values.value_or(ValueMode::Absolute);
    const std::vector<double> plus = table.writtenValuesUm(true, sign, mode);
    const std::vector<double> minus = table.writtenValuesUm(false, sign, mode);
    QByteArray& text = result.text;
    // The uncertainty column last, so that a reader of the first columns
    // reads the table as before.
    const bool uncertain = table.uncertainty_um.size() == table.size();
    const QByteArray column = csvValueColumn(sign, mode);
    text += "position_mm," + column + "_um";
    if (table.bidirectional) text += ',' + column + "_minus_um";
    text += uncertain ? ",uncertainty_um\n" : "\n";
    for (std::size_t i = 0; i < table.size(); ++i) {
        text += fixed(table.position_mm[i], 4) + ',' + fixed(plus[i], 3);
        if (table.bidirectional) text += ',' + fixed(minus[i], 3);
        text += uncertain ? ',' + fixed(table.uncertainty_um[i], 3) + '\n' : QByteArray("\n");
    }
    return result;
}

}  // namespace driftlab::compensation
