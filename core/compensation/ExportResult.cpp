#include "core/compensation/ExportResult.h"

#include <cmath>

namespace driftlab::compensation {

QByteArray fixed(double value, int decimals) {
    // QByteArray::number is locale-independent (always '.'), unlike QLocale.
    QByteArray text = QByteArray::number(value, 'f', decimals);
    if (text.startsWith('-') && text.mid(1).count('0') + text.mid(1).count('.') == text.size() - 1)
        text.remove(0, 1);
    return text;
}

QByteArray signedFixed(double value, int decimals) {
    const QByteArray text = fixed(value, decimals);
    return text.startsWith('-') ? text : '+' + text;
}

}  // namespace driftlab::compensation
