#include "core/interferometer/EnvironmentCorrection.h"

#include <stdexcept>

namespace driftlab::interferometer {

EnvironmentCorrection noCorrection() {
    EnvironmentCorrection c;
    c.description = QStringLiteral("none: the interferometer compensated itself");
    return c;
}

EnvironmentCorrection edlenCorrection(const AirState& air, double assumedIndex,
                                      double vacuumWavelength_nm) {
    if (const auto problem = airStateProblem(air))
        throw std::invalid_argument(problem->toStdString());
    if (!(assumedIndex >= 1.0 && assumedIndex < 1.001))
        throw std::invalid_argument(
            QStringLiteral("assumed refractive index %1 is not one of air or vacuum (1…1.001)")
                .arg(assumedIndex, 0, 'g', 12)
                .toStdString());
    EnvironmentCorrection c;
    c.applied = true;
    c.refractiveIndex = edlenRefractiveIndex(air, vacuumWavelength_nm);
    c.factor = assumedIndex / c.refractiveIndex;
    c.correction_ppm = (c.factor - 1.0) * 1e6;
    // U+2212 for the minus: the record is read by people, not parsed.
    QString ppm = QString::number(c.correction_ppm, 'f', 2);
    if (ppm.startsWith(u'-')) ppm.replace(0, 1, QChar(0x2212));
    c.description = QStringLiteral("Edlén, %1 °C, %2 kPa, %3 %RH: %4 ppm")
                        .arg(air.temperature_C, 0, 'f', 1)
                        .arg(air.pressure_Pa / 1000.0, 0, 'f', 1)
                        .arg(air.humidity_pct, 0, 'f', 0)
                        .arg(ppm);
    return c;
}

double standardAirIndex(double vacuumWavelength_nm) {
    return edlenRefractiveIndex(AirState{20.0, 101'325.0, 50.0, 450.0}, vacuumWavelength_nm);
}

}  // namespace driftlab::interferometer
