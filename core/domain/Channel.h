#pragma once
// A sensor channel of a campaign: what it measures (quantity) and what it is
// attached to (role). Models find channels by role, never by id.

#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

namespace driftlab {

enum class Quantity { Temperature, Displacement, Speed };

enum class ChannelRole {
    // temperature
    Nut,
    Bearing,
    Ambient,
    Air,
    Structure,
    Motor,
    Spindle,
    Other,
    // displacement (drift probes of a spindle or ETVE test)
    DriftX,
    DriftY,
    DriftZ,
    TiltA,
    TiltB,
    Drift,
};

QString toString(Quantity quantity);
QString toString(ChannelRole role);
std::optional<Quantity> quantityFromString(const QString& text);
std::optional<ChannelRole> roleFromString(const QString& text);
/// The unit every value of this quantity is stored in (docs/architecture.md).
QString unitOf(Quantity quantity);
/// Whether a role makes sense for a quantity (e.g. `nut` is a temperature role).
bool roleAllowedFor(Quantity quantity, ChannelRole role);
/// The names of the roles a quantity allows ("nut", "bearing", …), in declaration order.
QStringList roleNamesFor(Quantity quantity);
/// Channel and run ids: [A-Za-z0-9_]+ so they can be CSV headers and file names.
bool isValidIdentifier(const QString& id);

struct Channel {
    QString id;
    Quantity quantity = Quantity::Temperature;
    ChannelRole role = ChannelRole::Other;
    QString location;
    std::optional<double> position_mm;
    QJsonObject extra;  ///< keys this version does not know, kept for lossless export

    bool operator==(const Channel&) const = default;
};

/// The optional axis columns of samples.csv, besides the declared channels.
inline const QString kPositionColumn = QStringLiteral("position_mm");
inline const QString kFeedColumn = QStringLiteral("feed_mm_min");
inline const QString kTorqueColumn = QStringLiteral("torque_Nm");
bool isAxisColumn(const QString& column);

}  // namespace driftlab
