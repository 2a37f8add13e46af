#pragma once
// How numbers and names read in a message. A value read from a file or typed
// in comes back digit for digit (up to 12 significant digits), with no
// trailing zeros and no locale; names are quoted as the user wrote them. One
// formatter for every error and note, so the same value never reads two ways.

#include <QString>
#include <QStringList>
#include <QStringView>
#include <string_view>

namespace driftlab {

inline QString numberText(double value) {
    return QString::number(value, 'g', 12);
}

/// A text read from a file (a cell, a header, a JSON value or key) as a message
/// shows it. Control and format characters are escaped (NUL as \0, tab, line
/// feed and carriage return as \t, \n, \r, others as \xNN or \u{NNNN}), so the
/// message stays one line that prints whole and does nothing to a terminal; a
/// text of more than 60 characters is cut to its first 60 and "… (N bytes)",
/// N its size in the file (`bytes`; -1: its size in UTF-8).
QString shownText(QStringView text, qsizetype bytes = -1);
/// shownText in single quotes, the shortening after them: 'warm', 'AAA…' (3000000 bytes).
QString quotedText(QStringView text, qsizetype bytes = -1);
/// quotedText of a cell's bytes (UTF-8), decoding no more of it than is shown.
QString quotedCell(std::string_view cell);

/// "'S1', 'S2'": run, channel or spelling names in a message.
inline QString quotedList(const QStringList& names) {
    QStringList quoted;
    for (const QString& name : names) quoted << quotedText(name);
    return quoted.join(QStringLiteral(", "));
}

}  // namespace driftlab
