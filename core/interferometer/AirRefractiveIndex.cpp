#include "core/interferometer/AirRefractiveIndex.h"

#include <cmath>

#include "core/domain/MessageText.h"

namespace driftlab::interferometer {
namespace {

constexpr double kKelvinOffset = 273.15;

double sigmaSquared_per_um2(double vacuumWavelength_nm) {
    const double lambda_um = vacuumWavelength_nm * 1e-3;
    return 1.0 / (lambda_um * lambda_um);
}

}  // namespace

double saturationVapourPressure_Pa(double temperature_C) {
    // IAPWS-IF97 region 4 (saturation line), the formula NIST uses above 0 °C;
    // below 0 °C it gives the pressure over supercooled water, which is what a
    // hygrometer's relative humidity refers to.
    constexpr double K1 = 1.16705214528e3, K2 = -7.24213167032e5, K3 = -1.70738469401e1,
                     K4 = 1.20208247025e4, K5 = -3.23255503223e6, K6 = 1.49151086135e1,
                     K7 = -4.82326573616e3, K8 = 4.05113405421e5, K9 = -2.38555575678e-1,
                     K10 = 6.50175348448e2;
    const double T = temperature_C + kKelvinOffset;
    const double omega = T + K9 / (T - K10);
    const double A = omega * omega + K1 * omega + K2;
    const double B = K3 * omega * omega + K4 * omega + K5;
    const double C = K6 * omega * omega + K7 * omega + K8;
    const double X = -B + std::sqrt(B * B - 4 * A * C);
    return 1e6 * std::pow(2 * C / X, 4);
}

double edlenRefractiveIndex(const AirState& air, double vacuumWavelength_nm) {
    const double s2 = sigmaSquared_per_um2(vacuumWavelength_nm);
    const double t = air.temperature_C;
    const double p = air.pressure_Pa;
    const double ns_minus_1 = 1e-8 * (8342.54 + 2406147.0 / (130.0 - s2) + 15998.0 / (38.9 - s2)) *
                              (1.0 + 0.534e-6 * (air.co2_ppm - 450.0));
    const double X = (1.0 + 1e-8 * (0.601 - 0.00972 * t) * p) / (1.0 + 0.003661 * t);
    const double ntp_minus_1 = p * ns_minus_1 * X / 96095.43;
    const double pv_Pa = air.humidity_pct / 100.0 * saturationVapourPressure_Pa(t);
    const double T = t + kKelvinOffset;
    return 1.0 + ntp_minus_1 - (292.75 / T) * (3.7345 - 0.0401 * s2) * 1e-10 * pv_Pa;
}

double ciddorRefractiveIndex(const AirState& air, double vacuumWavelength_nm) {
    const double s2 = sigmaSquared_per_um2(vacuumWavelength_nm);
    const double t = air.temperature_C;
    const double T = t + kKelvinOffset;
    const double p = air.pressure_Pa;
    constexpr double R = 8.314472, Mv = 0.018015, Za = 0.9995922115, rho_vs = 0.00985938;
    constexpr double pR1 = 101'325.0, TR1 = 288.15;

    // Refractivities of standard dry air (15 °C, 101325 Pa, 450 ppm) and of
    // standard water vapour (20 °C, 1333 Pa).
    const double r_as = 1e-8 * (5792105.0 / (238.0185 - s2) + 167917.0 / (57.362 - s2));
    const double r_vs =
        1.022e-8 * (295.235 + 2.6422 * s2 - 0.03238 * s2 * s2 + 0.004028 * s2 * s2 * s2);
    const double r_axs = r_as * (1.0 + 0.534e-6 * (air.co2_ppm - 450.0));
    const double Ma = 0.0289635 + 1.2011e-8 * (air.co2_ppm - 400.0);

    // Mole fraction of water vapour, with the enhancement factor of moist air.
    const double f = 1.00062 + 3.14e-8 * p + 5.6e-7 * t * t;
    const double xv = f * air.humidity_pct / 100.0 * saturationVapourPressure_Pa(t) / p;

    const double pT = p / T;
    const double Zm =
        1.0 -
        pT * (1.58123e-6 + -2.9331e-8 * t + 1.1043e-10 * t * t + (5.707e-6 + -2.051e-8 * t) * xv +
              (1.9898e-4 + -2.376e-6 * t) * xv * xv) +
        pT * pT * (1.83e-11 + -0.765e-8 * xv * xv);
    const double rho_axs = pR1 * Ma / (Za * R * TR1);
    const double rho_v = xv * p * Mv / (Zm * R * T);
    const double rho_a = (1.0 - xv) * p * Ma / (Zm * R * T);
    return 1.0 + (rho_a / rho_axs) * r_axs + (rho_v / rho_vs) * r_vs;
}

std::optional<QString> airStateProblem(const AirState& air) {
    const double t = air.temperature_C, p = air.pressure_Pa, h = air.humidity_pct;
    if (!std::isfinite(t) || !std::isfinite(p) || !std::isfinite(h) || !std::isfinite(air.co2_ppm))
        return QStringLiteral("NaN or infinite air reading");
    if (t < -10.0 || t > 50.0)
        return QStringLiteral("air temperature %1 °C is outside −10…50 °C%2")
            .arg(numberText(t))
            .arg(t > 253 && t < 333 ? QStringLiteral(" (kelvin? DriftLab expects °C)") : QString());
    if (p < 60'000.0 || p > 120'000.0) {
        QString hint;
        if (p >= 600 && p <= 1200)
            hint = QStringLiteral(" (hPa? DriftLab expects Pa)");
        else if (p >= 60 && p <= 120)
            hint = QStringLiteral(" (kPa? DriftLab expects Pa)");
        else if (p >= 0.6 && p <= 1.2)
            hint = QStringLiteral(" (bar? DriftLab expects Pa)");
        return QStringLiteral("air pressure %1 Pa is outside 60000…120000 Pa%2")
            .arg(numberText(p))
            .arg(hint);
    }
    if (h < 0.0 || h > 100.0)
        return QStringLiteral("relative humidity %1 % is outside 0…100 %").arg(numberText(h));
    if (air.co2_ppm < 0.0 || air.co2_ppm > 2000.0)
        return QStringLiteral("CO2 %1 ppm is outside 0…2000 ppm").arg(numberText(air.co2_ppm));
    return std::nullopt;
}

}  // namespace driftlab::interferometer
