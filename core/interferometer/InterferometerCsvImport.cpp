#include "core/interferometer/InterferometerCsvImport.h"

#include <QFile>
#include <QFileInfo>
#include <cmath>
#include <memory>

#include "core/bundle/CsvTable.h"

namespace driftlab::interferometer {
namespace {

QByteArray exact(double value) {
    return QByteArray::number(value, 'g', 17);  // round-trips through from_chars
}

}  // namespace

InterferometerCsvImport importInterferometerCsv(const QString& path,
                                                const InterferometerHeader& header,
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
        const int time = table.requireColumn(QStringLiteral("time_s"));
        const int position = table.requireColumn(QStringLiteral("position_mm"));
        const int deviation = table.requireColumn(QStringLiteral("deviation_um"));
        const int air = table.column(QStringLiteral("air_C"));
        const int pressure = table.column(QStringLiteral("pressure_Pa"));
        const int humidity = table.column(QStringLiteral("humidity_pct"));
        const int material = table.column(QStringLiteral("material_C"));
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

        // The parser's field names map back to this file's columns for errors.
        const auto columnOf = [&](const QString& field) {
            const int c = table.column(field);
            return c >= 0 ? c : -1;
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
                table.fail(columnOf(e.field()), e.message());
            }
        }
    } catch (const bundle::BundleException& e) {
        result.error = e.error;
    }
    return result;
}

}  // namespace driftlab::interferometer
