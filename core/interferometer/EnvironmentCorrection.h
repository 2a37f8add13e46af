#pragma once
// Correcting a laser interferometer's length for the air it was measured in.
//
// The interferometer counts N half-wavelengths of its beam in air:
//   L = N·λ_vac / (2·n)
// With its own environmental compensation OFF it converted N with a fixed
// index n0 (vacuum, n0 = 1, or a nominal air), so it reported
//   L_reading = N·λ_vac / (2·n0)   and therefore   L_true = L_reading · n0 / n.
// Sign: air denser than assumed (n > n0: colder, higher pressure) makes the
// true length SHORTER than the reading; the correction in ppm is
// (n0/n − 1)·1e6, negative then. With n0 = 1 (vacuum) it is about −270 ppm.
//
// Only the air (the beam path) is corrected here. The material temperature is
// NOT used to normalise the length to 20 °C: DriftLab measures thermal growth,
// and normalising would remove the very error being measured.

#include <QString>

#include "core/interferometer/AirRefractiveIndex.h"

namespace driftlab::interferometer {

struct EnvironmentCorrection {
    bool applied = false;
    double factor = 1.0;         ///< L_true / L_reading = n0 / n
    double correction_ppm = 0;   ///< (factor − 1)·1e6
    double refractiveIndex = 0;  ///< n of the actual air (Edlén); 0 when not applied
    QString description;         ///< says which correction was applied, for the record

    double correctedLength_mm(double reading_mm) const { return reading_mm * factor; }
    /// deviation = actual − target; the target is exact, the actual length is
    /// scaled: deviation_true = deviation_reading + position_reading·(factor − 1).
    double correctedDeviation_um(double position_reading_mm, double deviation_reading_um) const {
        return deviation_reading_um + position_reading_mm * 1000.0 * (factor - 1.0);
    }
};

/// The interferometer compensated itself: nothing to do, and the record says so.
EnvironmentCorrection noCorrection();

/// The correction of a reading converted with the fixed index `assumedIndex`
/// (n0) when the air was `air`, at `vacuumWavelength_nm`, by the updated Edlén
/// equation. Description e.g. "Edlén, 20.3 °C, 101.1 kPa, 45 %RH: −2.13 ppm".
/// Throws std::invalid_argument naming the problem when the air is out of range.
EnvironmentCorrection edlenCorrection(const AirState& air, double assumedIndex,
                                      double vacuumWavelength_nm = kHeNeVacuumWavelength_nm);

/// n0 of "standard air" as many interferometers assume it with compensation
/// off: 20 °C, 101325 Pa, 50 %RH, 450 ppm CO2 by Edlén at the wavelength.
double standardAirIndex(double vacuumWavelength_nm = kHeNeVacuumWavelength_nm);

}  // namespace driftlab::interferometer
