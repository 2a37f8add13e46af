#include "core/interferometer/InterferometerColumns.h"

#include <QStringList>

#include "core/bundle/ColumnSpelling.h"

namespace driftlab::interferometer {

QString layoutColumn(ReadingRole role) {
    switch (role) {
        case ReadingRole::Time:
            return QStringLiteral("time_s");
        case ReadingRole::Position:
            return QStringLiteral("position_mm");
        case ReadingRole::Deviation:
            return QStringLiteral("deviation_um");
        case ReadingRole::Air:
            return QStringLiteral("air_C");
        case ReadingRole::Pressure:
            return QStringLiteral("pressure_Pa");
        case ReadingRole::Humidity:
            return QStringLiteral("humidity_pct");
        case ReadingRole::Material:
            return QStringLiteral("material_C");
    }
    return {};
}

QString roleLabel(ReadingRole role) {
    switch (role) {
        case ReadingRole::Time:
            return QStringLiteral("time [s]");
        case ReadingRole::Position:
            return QStringLiteral("position [mm]");
        case ReadingRole::Deviation:
            return QStringLiteral("deviation [µm]");
        case ReadingRole::Air:
            return QStringLiteral("air temperature [°C]");
        case ReadingRole::Pressure:
            return QStringLiteral("air pressure [Pa]");
        case ReadingRole::Humidity:
            return QStringLiteral("humidity [%]");
        case ReadingRole::Material:
            return QStringLiteral("material temperature [°C]");
    }
    return {};
}

bool isRequired(ReadingRole role) {
    return role == ReadingRole::Time || role == ReadingRole::Position ||
           role == ReadingRole::Deviation;
}

namespace {

/// Words vendor exports put in a role's header, lower case. "target" is
/// never the position: it is the nominal the machine was sent to.
QStringList wordsOf(ReadingRole role) {
    switch (role) {
        case ReadingRole::Time:
            return {QStringLiteral("time"), QStringLiteral("zeit")};
        case ReadingRole::Position:
            return {QStringLiteral("position"), QStringLiteral("pos")};
        case ReadingRole::Deviation:
            return {QStringLiteral("deviation"), QStringLiteral("error"),
                    QStringLiteral("abweichung")};
        case ReadingRole::Air:
            return {QStringLiteral("air")};
        case ReadingRole::Pressure:
            return {QStringLiteral("pressure")};
        case ReadingRole::Humidity:
            return {QStringLiteral("humidity")};
        case ReadingRole::Material:
            return {QStringLiteral("material")};
    }
    return {};
}

}  // namespace

std::optional<int> guessColumn(ReadingRole role, const std::vector<QString>& header) {
    for (std::size_t i = 0; i < header.size(); ++i)
        if (bundle::spellsColumn(header[i], layoutColumn(role))) return int(i);
    for (const QString& word : wordsOf(role))
        for (std::size_t i = 0; i < header.size(); ++i) {
            const QString h = header[i].toLower();
            if (h.contains(QStringLiteral("target"))) continue;
            // "Air pressure" and "air humidity" are the air's other quantities.
            if (role == ReadingRole::Air &&
                (h.contains(QStringLiteral("pressure")) || h.contains(QStringLiteral("humid"))))
                continue;
            if (h.startsWith(word) || h.contains(QLatin1Char(' ') + word)) return int(i);
        }
    return std::nullopt;
}

}  // namespace driftlab::interferometer
