#include "core/iso/MeasurementUncertainty.h"

#include <cmath>

#include "core/domain/MessageText.h"

namespace driftlab::iso {

namespace {

/// A ±a accuracy read as a rectangular distribution.
double rectangular(double halfWidth) {
    return halfWidth / std::sqrt(3.0);
}

QString um(double value) {
    return QString::number(value, 'f', 3) + QStringLiteral(" µm");
}

}  // namespace

EdlenSensitivities edlenSensitivities(const interferometer::AirState& air) {
    // Steps small against the shop floor's range, large against rounding
    // (n − 1 ≈ 2.7e-4 carries ~12 significant digits in a double).
    const auto slope = [&air](auto change, double step) {
        interferometer::AirState low = air, high = air;
        change(low, -step);
        change(high, step);
        return std::abs(interferometer::edlenRefractiveIndex(high) -
                        interferometer::edlenRefractiveIndex(low)) /
               (2 * step);
    };
    EdlenSensitivities s;
    s.per_K = slope([](interferometer::AirState& a, double d) { a.temperature_C += d; }, 0.5);
    s.per_hPa = slope([](interferometer::AirState& a, double d) { a.pressure_Pa += 100 * d; }, 5);
    s.per_pct = slope([](interferometer::AirState& a, double d) { a.humidity_pct += d; }, 5);
    return s;
}

const ParameterUncertainty* UncertaintyBudget::find(const QString& parameter) const {
    for (const ParameterUncertainty& p : parameters)
        if (p.parameter == parameter) return &p;
    return nullptr;
}

const UncertaintyContribution* UncertaintyBudget::contribution(const QString& key) const {
    for (const UncertaintyContribution& c : contributions)
        if (c.key == key) return &c;
    return nullptr;
}

UncertaintyBudget uncertaintyBudget(const SetupUncertainty& setup,
                                    const UncertaintyConditions& conditions) {
    UncertaintyBudget budget;
    budget.conditions = conditions;
    budget.coverage_k = setup.coverage_k;
    const double length_um = conditions.length_mm * 1000;
    const double L_m = conditions.length_mm / 1000;
    auto add = [&budget](QString key, QString name, QString equation, double value,
                         bool lengthDependent) {
        budget.contributions.push_back(
            {std::move(key), std::move(name), std::move(equation), value, lengthDependent});
    };

    add(QStringLiteral("device"), QStringLiteral("measuring device (calibration)"),
        QStringLiteral("(U0 + U_L·L)/k = (%1 + %2·%3 m)/%4")
            .arg(numberText(setup.device_um), numberText(setup.device_ppm), numberText(L_m),
                 numberText(setup.device_k)),
        (setup.device_um + setup.device_ppm * L_m) / setup.device_k, true);
    add(QStringLiteral("device_at_target"),
        QStringLiteral("measuring device, length-independent part"),
        QStringLiteral("U0/k = %1/%2").arg(numberText(setup.device_um), numberText(setup.device_k)),
        setup.device_um / setup.device_k, false);

    const EdlenSensitivities s = edlenSensitivities(conditions.air);
    const double uT = s.per_K * rectangular(setup.air_temperature_K);
    const double up = s.per_hPa * rectangular(setup.air_pressure_hPa);
    const double uRH = s.per_pct * rectangular(setup.air_humidity_pct);
    add(QStringLiteral("environment"),
        QStringLiteral("environmental compensation (air temperature, pressure, humidity)"),
        QStringLiteral("L·√((%1e-6/K·%2 K)² + (%3e-6/hPa·%4 hPa)² + (%5e-6/%RH·%6 %RH)²)/√3")
            .arg(QString::number(s.per_K * 1e6, 'f', 3), numberText(setup.air_temperature_K),
                 QString::number(s.per_hPa * 1e6, 'f', 3), numberText(setup.air_pressure_hPa),
                 QString::number(s.per_pct * 1e6, 'f', 4), numberText(setup.air_humidity_pct)),
        length_um * std::sqrt(uT * uT + up * up + uRH * uRH), true);

    add(QStringLiteral("material_temperature"), QStringLiteral("machine temperature measurement"),
        QStringLiteral("α·L·a_θ/√3 = %1/K·%2 mm·%3 K/√3")
            .arg(numberText(conditions.expansion_per_K), numberText(conditions.length_mm),
                 numberText(setup.material_temperature_K)),
        conditions.expansion_per_K * length_um * rectangular(setup.material_temperature_K), true);

    const double dT_K = std::abs(conditions.material_temperature_C - 20);
    add(QStringLiteral("expansion"), QStringLiteral("expansion coefficient (20 °C normalisation)"),
        QStringLiteral("L·|θ − 20 °C|·a_α/√3 = %1 mm·%2 K·%3/K/√3")
            .arg(numberText(conditions.length_mm), QString::number(dT_K, 'f', 2),
                 numberText(setup.expansion_per_K)),
        length_um * dT_K * rectangular(setup.expansion_per_K), true);

    // The cosine error only shortens the measured length, from 0 (aligned) to
    // e = L·(1 − cos φ): a rectangular distribution of width e.
    const double angle_rad =
        conditions.length_mm > 0 ? std::atan(setup.misalignment_mm / conditions.length_mm) : 0;
    const double cosine_um = length_um * (1 - std::cos(angle_rad));
    add(QStringLiteral("misalignment"), QStringLiteral("misalignment (cosine error)"),
        QStringLiteral("L·(1 − cos φ)/(2√3), tan φ = %1 mm/%2 mm: e = %3")
            .arg(numberText(setup.misalignment_mm), numberText(conditions.length_mm),
                 um(cosine_um)),
        cosine_um / (2 * std::sqrt(3.0)), true);

    add(QStringLiteral("eve"), QStringLiteral("environmental variation error (machine at rest)"),
        QStringLiteral("EVE/(2√3) = %1/(2√3), from %2")
            .arg(um(conditions.eve_um), conditions.eve_source.isEmpty()
                                            ? QStringLiteral("nothing: not measured")
                                            : conditions.eve_source),
        conditions.eve_um / (2 * std::sqrt(3.0)), false);

    // Values that span the travel (E, M, A) take every contributor at the
    // full length. R and B compare readings at one target, taken minutes
    // apart: a length-proportional error is the same for both and cancels;
    // what stays is the device's length-independent part and the environment's
    // variation over the test.
    const QStringList spanning{QStringLiteral("device"),
                               QStringLiteral("environment"),
                               QStringLiteral("material_temperature"),
                               QStringLiteral("expansion"),
                               QStringLiteral("misalignment"),
                               QStringLiteral("eve")};
    const QStringList atOneTarget{QStringLiteral("device_at_target"), QStringLiteral("eve")};
    for (const QString& parameter : iso230_2ParameterKeys()) {
        const bool span = parameter.startsWith(QLatin1Char('A')) ||
                          parameter.startsWith(QLatin1Char('E')) || parameter == QLatin1String("M");
        ParameterUncertainty p;
        p.parameter = parameter;
        p.contributors = span ? spanning : atOneTarget;
        double sum = 0;
        for (const QString& key : p.contributors) {
            const double u = budget.contribution(key)->standard_um;
            sum += u * u;
        }
        p.combined_um = std::sqrt(sum);
        p.expanded_um = setup.coverage_k * p.combined_um;
        budget.parameters.push_back(p);
    }

    const auto unset = [&budget](double value, const QString& what) {
        if (value == 0) budget.notes << QStringLiteral("%1 not given: counted as 0 µm").arg(what);
    };
    unset(setup.device_um + setup.device_ppm, QStringLiteral("interferometer calibration"));
    unset(setup.air_temperature_K + setup.air_pressure_hPa + setup.air_humidity_pct,
          QStringLiteral("environment sensor accuracies"));
    unset(setup.material_temperature_K, QStringLiteral("material thermometer accuracy"));
    unset(setup.expansion_per_K, QStringLiteral("expansion coefficient uncertainty"));
    unset(setup.misalignment_mm, QStringLiteral("beam misalignment"));
    unset(conditions.eve_um, QStringLiteral("environmental variation error (no ETVE run)"));
    return budget;
}

}  // namespace driftlab::iso
