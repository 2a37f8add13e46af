#include "core/domain/Channel.h"

#include <QRegularExpression>
#include <array>
#include <utility>

namespace driftlab {
namespace {

constexpr std::array<std::pair<Quantity, const char*>, 3> kQuantities{{
    {Quantity::Temperature, "temperature"},
    {Quantity::Displacement, "displacement"},
    {Quantity::Speed, "speed"},
}};

constexpr std::array<std::pair<ChannelRole, const char*>, 14> kRoles{{
    {ChannelRole::Nut, "nut"},
    {ChannelRole::Bearing, "bearing"},
    {ChannelRole::Ambient, "ambient"},
    {ChannelRole::Air, "air"},
    {ChannelRole::Structure, "structure"},
    {ChannelRole::Motor, "motor"},
    {ChannelRole::Spindle, "spindle"},
    {ChannelRole::Other, "other"},
    {ChannelRole::DriftX, "drift_x"},
    {ChannelRole::DriftY, "drift_y"},
    {ChannelRole::DriftZ, "drift_z"},
    {ChannelRole::TiltA, "tilt_a"},
    {ChannelRole::TiltB, "tilt_b"},
    {ChannelRole::Drift, "drift"},
}};

template <typename Enum, std::size_t N>
QString nameOf(const std::array<std::pair<Enum, const char*>, N>& table, Enum value) {
    for (const auto& [e, name] : table)
        if (e == value) return QString::fromLatin1(name);
    return {};
}

/// Hand-written campaign files spell a name "Drift_X", "drift-x" or "drift x":
/// the same name, read in any case with '-' or a space for '_'.
template <typename Enum, std::size_t N>
std::optional<Enum> valueOf(const std::array<std::pair<Enum, const char*>, N>& table,
                            const QString& text) {
    QString spelled = text.trimmed().toLower();
    spelled.replace(QLatin1Char('-'), QLatin1Char('_')).replace(QLatin1Char(' '), QLatin1Char('_'));
    for (const auto& [e, name] : table)
        if (spelled == QLatin1String(name)) return e;
    return std::nullopt;
}

}  // namespace

QString toString(Quantity quantity) {
    return nameOf(kQuantities, quantity);
}
QString toString(ChannelRole role) {
    return nameOf(kRoles, role);
}
std::optional<Quantity> quantityFromString(const QString& text) {
    return valueOf(kQuantities, text);
}
std::optional<ChannelRole> roleFromString(const QString& text) {
    return valueOf(kRoles, text);
}

QString unitOf(Quantity quantity) {
    switch (quantity) {
        case Quantity::Temperature:
            return QStringLiteral("°C");
        case Quantity::Displacement:
            return QStringLiteral("µm");
        case Quantity::Speed:
            return QStringLiteral("rpm");
    }
    return {};
}

bool roleAllowedFor(Quantity quantity, ChannelRole role) {
    switch (quantity) {
        case Quantity::Temperature:
            return role <= ChannelRole::Other;
        case Quantity::Displacement:
            return role >= ChannelRole::DriftX;
        case Quantity::Speed:
            return role == ChannelRole::Spindle;
    }
    return false;
}

QStringList roleNamesFor(Quantity quantity) {
    QStringList names;
    for (const auto& [role, name] : kRoles)
        if (roleAllowedFor(quantity, role)) names << QString::fromLatin1(name);
    return names;
}

bool isValidIdentifier(const QString& id) {
    static const QRegularExpression pattern(QStringLiteral("^[A-Za-z0-9_]+$"));
    return pattern.match(id).hasMatch();
}

bool isAxisColumn(const QString& column) {
    return column == kPositionColumn || column == kFeedColumn || column == kTorqueColumn;
}

}  // namespace driftlab
