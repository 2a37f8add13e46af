#pragma once
// The refractive index of air at a laser's vacuum wavelength, from the air's
// temperature, pressure, humidity and CO2 content. A laser interferometer
// counts fringes of λ_air = λ_vac / n, so a length it reports scales with 1/n:
// 1 K of air temperature is about 1 ppm of length (see EnvironmentCorrection).
//
// Two independent equations, both in the form the NIST Engineering Metrology
// Toolbox documents ("Index of Refraction of Air", J. A. Stone and
// J. H. Zimmerman, emtoolbox.nist.gov/Wavelength/Documentation.asp, Appendix A):
//  - edlenRefractiveIndex: Edlén (1966) as updated by Birch & Downs (Metrologia
//    30, 155 (1993); correction Metrologia 31, 315 (1994)), with NIST's
//    292.75/T factor on the water-vapour term, which keeps it accurate on a shop
//    floor away from 20 °C. DriftLab's default.
//  - ciddorRefractiveIndex: Ciddor (Appl. Opt. 35, 1566 (1996)), the
//    cross-check; the two agree within ~2e-8 at lab conditions.

#include <QString>
#include <optional>

namespace driftlab::interferometer {

/// HeNe red line in vacuum (632.991 nm; 633 nm is the rounded value).
inline constexpr double kHeNeVacuumWavelength_nm = 632.991;

struct AirState {
    double temperature_C = 20.0;
    double pressure_Pa = 101'325.0;
    double humidity_pct = 50.0;  ///< relative humidity over water, 0…100 %
    double co2_ppm = 450.0;      ///< Birch & Downs' reference CO2 content
};

/// Saturation vapour pressure over water (IAPWS-IF97, as in NIST's Appendix A-I).
double saturationVapourPressure_Pa(double temperature_C);

/// n by the updated Edlén equation (Birch & Downs 1993/1994, NIST's form):
///   σ² = 1/λ_vac² (λ in µm)
///   (n_s − 1)·1e8 = 8342.54 + 2406147/(130 − σ²) + 15998/(38.9 − σ²)
///       (dry air, 15 °C, 101325 Pa, 450 ppm CO2)
///   X = (1 + 1e-8·(0.601 − 0.00972·t)·p) / (1 + 0.003661·t)
///   n_tp − 1 = p·(n_s − 1)·X / 96095.43
///   n = n_tp − (292.75/T)·(3.7345 − 0.0401·σ²)·1e-10·p_v
/// with t in °C, T = t + 273.15 K, p and the water vapour pressure p_v in Pa.
/// CO2 other than 450 ppm scales the dry term by 1 + 0.534e-6·(x_CO2 − 450)
/// (Ciddor's CO2 factor; Birch & Downs give none: NIST's Edlén takes no CO2).
double edlenRefractiveIndex(const AirState& air,
                            double vacuumWavelength_nm = kHeNeVacuumWavelength_nm);

/// n by Ciddor (1996) with the BIPM 1981/91 compressibility, as NIST gives it
/// (Appendix A-III), water vapour pressure from saturationVapourPressure_Pa().
double ciddorRefractiveIndex(const AirState& air,
                             double vacuumWavelength_nm = kHeNeVacuumWavelength_nm);

/// Why `air` is outside the range DriftLab corrects for (−10…50 °C air,
/// 60…120 kPa, 0…100 %RH, 0…2000 ppm CO2), naming the likely unit mix-up
/// (kelvin; hPa, kPa or bar for Pa; a 0…1 fraction is not detectable), or nothing.
std::optional<QString> airStateProblem(const AirState& air);

}  // namespace driftlab::interferometer
