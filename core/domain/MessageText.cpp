#include "core/domain/MessageText.h"

#include <algorithm>
#include <utility>

namespace driftlab {
namespace {

constexpr qsizetype kShownCharacters = 60;

void appendEscaped(QString& out, QChar c) {
    switch (c.unicode()) {
        case 0:
            out += QLatin1String("\\0");
            return;
        case '\t':
            out += QLatin1String("\\t");
            return;
        case '\n':
            out += QLatin1String("\\n");
            return;
        case '\r':
            out += QLatin1String("\\r");
            return;
    }
    if (c.unicode() < 0x20 || c.unicode() == 0x7F)
        out += QStringLiteral("\\x%1").arg(c.unicode(), 2, 16, QLatin1Char('0'));
    // C1 controls, bidirectional overrides, line and paragraph separators:
    // invisible, or able to reorder or break the line on a terminal.
    else if (const QChar::Category category = c.category();
             category == QChar::Other_Control || category == QChar::Other_Format ||
             category == QChar::Separator_Line || category == QChar::Separator_Paragraph)
        out += QStringLiteral("\\u{%1}").arg(c.unicode(), 4, 16, QLatin1Char('0'));
    else
        out += c;
}

/// The shown part, escaped, and whether the text was cut.
std::pair<QString, bool> shownPart(QStringView text) {
    qsizetype shown = std::min(text.size(), kShownCharacters);
    if (shown < text.size() && text[shown - 1].isHighSurrogate()) --shown;  // whole characters
    QString out;
    out.reserve(shown);
    for (qsizetype i = 0; i < shown; ++i) appendEscaped(out, text[i]);
    return {out, shown < text.size()};
}

QString sizeNote(QStringView text, qsizetype bytes) {
    return QStringLiteral("(%1 bytes)").arg(bytes >= 0 ? bytes : text.toUtf8().size());
}

}  // namespace

QString shownText(QStringView text, qsizetype bytes) {
    auto [out, cut] = shownPart(text);
    return cut ? out + QStringLiteral("… ") + sizeNote(text, bytes) : out;
}

QString quotedText(QStringView text, qsizetype bytes) {
    auto [out, cut] = shownPart(text);
    return QLatin1Char('\'') + out +
           (cut ? QStringLiteral("…' ") + sizeNote(text, bytes) : QStringLiteral("'"));
}

QString quotedCell(std::string_view cell) {
    // Enough bytes for the shown characters at four bytes each, and one more.
    const std::size_t decoded = std::min(cell.size(), std::size_t(kShownCharacters + 1) * 4);
    return quotedText(QString::fromUtf8(cell.data(), qsizetype(decoded)), qsizetype(cell.size()));
}

}  // namespace driftlab
