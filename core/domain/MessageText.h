#pragma once
// How numbers and names read in a message. A value read from a file or typed
// in comes back digit for digit (up to 12 significant digits), with no
// trailing zeros and no locale; names are quoted as the user wrote them. One
// formatter for every error and note, so the same value never reads two ways.

#include <QString>
#include <QStringList>

namespace driftlab {

inline QString numberText(double value) {
    return QString::number(value, 'g', 12);
}

/// "'S1', 'S2'": run, channel or spelling names in a message.
inline QString quotedList(const QStringList& names) {
    return names.isEmpty()
               ? QString()
               : QLatin1Char('\'') + names.join(QStringLiteral("', '")) + QLatin1Char('\'');
}

}  // namespace driftlab
