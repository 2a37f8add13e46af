#include "core/domain/Units.h"

#include <QStringList>

namespace driftlab {
namespace {

struct KnownUnit {
    QStringList spellings;  ///< compared without spaces, case-insensitively
    UnitConversion conversion;
};

/// The units of `quantity` DriftLab reads, its own first.
std::vector<KnownUnit> knownUnits(Quantity quantity) {
    switch (quantity) {
        case Quantity::Temperature:
            return {
                {{QStringLiteral("°C"), QStringLiteral("degC"), QStringLiteral("C"),
                  QStringLiteral("℃"), QStringLiteral("celsius")},
                 {}},
                {{QStringLiteral("°F"), QStringLiteral("degF"), QStringLiteral("F"),
                  QStringLiteral("℉"), QStringLiteral("fahrenheit")},
                 {QString(), 32.0, 5.0, 9.0}},
                {{QStringLiteral("K"), QStringLiteral("kelvin")}, {QString(), 273.15, 1.0, 1.0}}};
        case Quantity::Displacement:
            return {{{QStringLiteral("µm"), QStringLiteral("um"), QStringLiteral("micron"),
                      QStringLiteral("microns")},
                     {}}};
        case Quantity::Speed:
            return {{{QStringLiteral("rpm"), QStringLiteral("1/min"), QStringLiteral("min^-1"),
                      QStringLiteral("min-1"), QStringLiteral("U/min")},
                     {}}};
    }
    return {};
}

}  // namespace

std::optional<UnitConversion> conversionToDriftLabUnit(Quantity quantity, const QString& unit,
                                                       QString* why) {
    // Loggers write "deg C", the Greek mu for the micro sign, …
    QString u = unit;
    u.remove(QLatin1Char(' ')).replace(QChar(0x03BC), QChar(0x00B5));
    const std::vector<KnownUnit> known = knownUnits(quantity);
    QStringList names;
    for (const KnownUnit& k : known) {
        if (k.spellings.contains(u, Qt::CaseInsensitive)) {
            UnitConversion conversion = k.conversion;
            conversion.from = unit;
            return conversion;
        }
        names << k.spellings.front();
    }
    const QString list = names.size() == 1
                             ? names.front()
                             : names.mid(0, names.size() - 1).join(QStringLiteral(", ")) +
                                   QStringLiteral(" or ") + names.back();
    *why = QStringLiteral("'%1' is not a unit DriftLab reads for a %2 channel (%3)")
               .arg(unit, toString(quantity), list);
    return std::nullopt;
}

}  // namespace driftlab
