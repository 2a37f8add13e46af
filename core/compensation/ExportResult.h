#pragma once
// What every exporter returns, and the number formatting they share.

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace driftlab::compensation {

/// The file text, or why there is none. Exporters never write files: the
/// caller saves the text atomically (QSaveFile) only when error is empty.
struct ExportResult {
    QByteArray text;
    QString error;  ///< empty on success; names the point and value at fault
    QStringList warnings;
    bool ok() const { return error.isEmpty(); }
};

/// `value` with `decimals` decimals, '.' as separator whatever the locale, and
/// never "-0.0000": a negative zero on a controller screen reads as a sign error.
QByteArray fixed(double value, int decimals);

/// As fixed(), with an explicit '+' on non-negative values (Heidenhain tables).
QByteArray signedFixed(double value, int decimals);

}  // namespace driftlab::compensation
