#include "core/bundle/ColumnSpelling.h"

#include "core/bundle/ValueLimits.h"

namespace driftlab::bundle {
namespace {

struct StemAndUnit {
    QString stem, unit;  ///< unit: null when the header gives none
};

/// A header split into its quantity and its unit: "time [s]", "time (s)",
/// "time_s" (the format's own way) or a bare "time".
StemAndUnit split(const QString& header) {
    if (const std::optional<HeaderWithUnit> bracketed = splitHeaderUnit(header))
        return {bracketed->id, bracketed->unit};
    const qsizetype cut = header.indexOf(QLatin1Char('_'));
    if (cut <= 0) return {header, QString()};
    return {header.left(cut), header.mid(cut + 1)};
}

/// A unit in one spelling: "N·m", "N m", "Nm" → "nm"; "µm", "μm", "um",
/// "micron" → "um"; "mm/min", "mm_min" → "mm_min"; "sec" → "s"; "°C" → "c";
/// "%" → "pct".
QString normalUnit(QString unit) {
    unit = unit.toLower();
    for (const QChar c : {QChar(u' '), QChar(u'·'), QChar(u'*'), QChar(u'.'), QChar(u'°')})
        unit.remove(c);
    unit.replace(QChar(u'µ'), QLatin1Char('u')).replace(QChar(u'μ'), QLatin1Char('u'));
    unit.replace(QLatin1Char('/'), QLatin1Char('_'));
    if (unit == QLatin1String("sec")) return QStringLiteral("s");
    if (unit == QLatin1String("micron") || unit == QLatin1String("microns"))
        return QStringLiteral("um");
    if (unit == QLatin1String("degc")) return QStringLiteral("c");
    if (unit == QLatin1String("%")) return QStringLiteral("pct");
    return unit;
}

}  // namespace

bool spellsColumn(const QString& header, const QString& name) {
    // Every spelling starts with the name's first letter (cells are trimmed):
    // a header of 100 000 channels is passed over without a pattern match.
    if (header.isEmpty() || name.isEmpty() || header.front().toLower() != name.front().toLower())
        return false;
    if (header.compare(name, Qt::CaseInsensitive) == 0) return true;
    const StemAndUnit want = split(name), have = split(header);
    return !want.unit.isNull() && !have.unit.isNull() &&
           have.stem.compare(want.stem, Qt::CaseInsensitive) == 0 &&
           normalUnit(have.unit) == normalUnit(want.unit);
}

std::optional<QString> otherUnitOf(const QString& header, const QString& name) {
    const StemAndUnit want = split(name), have = split(header);
    if (want.unit.isNull() || have.stem.compare(want.stem, Qt::CaseInsensitive) != 0)
        return std::nullopt;
    if (have.unit.isNull()) return QString();
    if (normalUnit(have.unit) == normalUnit(want.unit)) return std::nullopt;
    return have.unit;
}

}  // namespace driftlab::bundle
