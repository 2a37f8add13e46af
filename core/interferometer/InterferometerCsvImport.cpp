#include "core/interferometer/InterferometerCsvImport.h"

#include <QFile>
#include <QFileInfo>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "core/bundle/CsvTable.h"
#include "core/domain/MessageText.h"

namespace driftlab::interferometer {
namespace {

QByteArray exact(double value) {
    return QByteArray::number(value, 'g', 17);  // round-trips through from_chars
}

/// The column of `role`: the mapped header exactly, or the layout's name as
/// other software spells it; -1 when absent (or mapped to none).
int columnOf(const bundle::CsvTable& table, const ColumnMapping& mapping, ReadingRole role) {
    const std::optional<QString>& mapped = mapping[role];
    if (!mapped)
        return isRequired(role) ? table.requireColumn(layoutColumn(role))
                                : table.column(layoutColumn(role));
    const auto& header = table.header();
    const auto it = std::find(header.begin(), header.end(), *mapped);
    if (it != header.end()) return int(it - header.begin());
    if (mapped->isEmpty() && !isRequired(role)) return -1;
    throw bundle::BundleException(
        {table.fileName(), 1, 0,
         mapped->isEmpty() ? QStringLiteral("no column is chosen for %1, which a reading needs")
                                 .arg(layoutColumn(role))
                           : QStringLiteral("missing column %1 (chosen for %2) in header")
                                 .arg(quotedText(*mapped), layoutColumn(role))});
}

}  // namespace

InterferometerCsvImport importInterferometerCsv(const QString& path,
                                                const InterferometerHeader& header,
                                                double maxEnvironmentAge_s) {
    return importInterferometerCsv(path, header, ColumnMapping{}, maxEnvironmentAge_s);
}

InterferometerCsvImport importInterferometerCsv(const QString& path,
                                                const InterferometerHeader& header,
                                                const ColumnMapping& mapping,
                                                double maxEnvironmentAge_s) {
    InterferometerCsvImport result;
    const QString name = QFileInfo(path).fileName();
    auto file = std::make_unique<QFile>(path);
    if (!file->open(QIODevice::ReadOnly)) {
        result.error = bundle::BundleError{name, 0, 0, file->errorString()};
        return result;
    }
    try {
        bundle::CsvTable table(std::move(file), name);
        std::array<int, kReadingRoles.size()> columns{};
        for (ReadingRole role : kReadingRoles)
            columns[std::size_t(role)] = columnOf(table, mapping, role);
        const int time = columns[std::size_t(ReadingRole::Time)];
        const int position = columns[std::size_t(ReadingRole::Position)];
        const int deviation = columns[std::size_t(ReadingRole::Deviation)];
        const int air = columns[std::size_t(ReadingRole::Air)];
        const int pressure = columns[std::size_t(ReadingRole::Pressure)];
        const int humidity = columns[std::size_t(ReadingRole::Humidity)];
        const int material = columns[std::size_t(ReadingRole::Material)];
        const bool hasAir = air >= 0 && pressure >= 0 && humidity >= 0;
        if (!hasAir && (air >= 0 || pressure >= 0 || humidity >= 0))
            throw bundle::BundleException(
                {name, 1, 0,
                 QStringLiteral("air_C, pressure_Pa and humidity_pct come "
                                "together: one or two of them is not the air")});
        if (!header.compensationOn && !hasAir)
            throw bundle::BundleException(
                {name, 1, 0,
                 QStringLiteral("the interferometer's compensation was off but "
                                "the file has no air_C, pressure_Pa and "
                                "humidity_pct columns to correct it with")});

        // The parser's field names (the layout's) map back to this file's
        // columns for errors.
        const auto fieldColumn = [&](const QString& field) {
            for (ReadingRole role : kReadingRoles)
                if (layoutColumn(role) == field) return columns[std::size_t(role)];
            return -1;
        };
        InterferometerSession session(maxEnvironmentAge_s);
        session.feed(QStringLiteral("header,compensation=%1,reference=%2,wavelength_nm=%3")
                         .arg(header.compensationOn ? QStringLiteral("on") : QStringLiteral("off"),
                              QString::fromLatin1(exact(header.assumedIndex)),
                              QString::fromLatin1(exact(header.vacuumWavelength_nm)))
                         .toStdString());
        while (table.next()) {
            try {
                const double t = table.number(time);
                if (hasAir) {
                    const double a = table.numberOrMissing(air);
                    const double p = table.numberOrMissing(pressure);
                    const double h = table.numberOrMissing(humidity);
                    const int present = !std::isnan(a) + !std::isnan(p) + !std::isnan(h);
                    if (present == 3) {
                        QByteArray env =
                            "env," + exact(t) + ',' + exact(a) + ',' + exact(p) + ',' + exact(h);
                        if (material >= 0 && !std::isnan(table.numberOrMissing(material)))
                            env += ',' + exact(table.numberOrMissing(material));
                        session.feed(env.toStdString());
                    } else if (present != 0) {
                        table.fail(std::isnan(a)   ? air
                                   : std::isnan(p) ? pressure
                                                   : humidity,
                                   QStringLiteral("empty while the other air cells of the row "
                                                  "are filled"));
                    }
                }
                const QByteArray reading = exact(t) + ',' + exact(table.number(position)) + ',' +
                                           exact(table.number(deviation));
                if (auto r = session.feed(reading.toStdString())) {
                    r->line = table.line();
                    result.correction = r->correction.description;
                    result.readings.push_back(std::move(*r));
                }
            } catch (const InterferometerLineError& e) {
                table.fail(fieldColumn(e.field()), e.message());
            }
        }
    } catch (const bundle::BundleException& e) {
        result.error = e.error;
    }
    return result;
}

}  // namespace driftlab::interferometer
