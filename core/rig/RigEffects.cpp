#include "core/rig/RigEffects.h"

#include <cmath>

namespace driftlab::rig {

bool RigEffects::any() const {
    return forced_convection_h1 != 0 || nut_heat_exponent != 1 || motor_heat_W_per_Nm2 != 0 ||
           !sensor_lag_s.empty() || !sensor_offset_K.empty() || air_refraction != 0 ||
           frame_growth_um_per_K != 0;
}

QStringList knownEffectIds() {
    return {QStringLiteral("forced_convection"),
            QStringLiteral("nut_heat_exponent"),
            QStringLiteral("motor_heat"),
            QStringLiteral("sensor_lag:<channel>"),
            QStringLiteral("sensor_offset:<channel>"),
            QStringLiteral("air_refraction"),
            QStringLiteral("frame_growth")};
}

bool applyEffect(RigEffects& effects, const QString& assignment, QString* error) {
    const qsizetype eq = assignment.indexOf(QLatin1Char('='));
    const QString id = assignment.left(eq).trimmed();
    bool ok = eq > 0;
    const double value = assignment.mid(eq + 1).trimmed().toDouble(&ok);
    auto fail = [&](const QString& why) {
        *error = QStringLiteral("effect '%1': %2").arg(assignment, why);
        return false;
    };
    if (eq <= 0) return fail(QStringLiteral("expected ID=VALUE"));
    if (!ok || !std::isfinite(value)) return fail(QStringLiteral("value is not a number"));

    const QString base = id.section(QLatin1Char(':'), 0, 0);
    const QString channel = id.section(QLatin1Char(':'), 1);
    const bool perChannel =
        base == QLatin1String("sensor_lag") || base == QLatin1String("sensor_offset");
    if (perChannel && channel.isEmpty())
        return fail(QStringLiteral("needs a channel: %1:<channel>=VALUE").arg(base));
    if (!perChannel && !channel.isEmpty()) return fail(QStringLiteral("takes no channel suffix"));

    if (base == QLatin1String("forced_convection")) {
        if (value < 0) return fail(QStringLiteral("h1 must not be negative"));
        effects.forced_convection_h1 = value;
    } else if (base == QLatin1String("nut_heat_exponent")) {
        if (value <= 0 || value > 3) return fail(QStringLiteral("exponent must be in (0, 3]"));
        effects.nut_heat_exponent = value;
    } else if (base == QLatin1String("motor_heat")) {
        if (value < 0) return fail(QStringLiteral("must not be negative"));
        effects.motor_heat_W_per_Nm2 = value;
    } else if (base == QLatin1String("sensor_lag")) {
        if (value < 0) return fail(QStringLiteral("lag must not be negative"));
        effects.sensor_lag_s[channel] = value;
    } else if (base == QLatin1String("sensor_offset")) {
        effects.sensor_offset_K[channel] = value;
    } else if (base == QLatin1String("air_refraction")) {
        if (value < 0 || value > 2) return fail(QStringLiteral("fraction must be in [0, 2]"));
        effects.air_refraction = value;
    } else if (base == QLatin1String("frame_growth")) {
        effects.frame_growth_um_per_K = value;
    } else {
        return fail(QStringLiteral("unknown effect id '%1' (known: %2)")
                        .arg(id, knownEffectIds().join(QStringLiteral(", "))));
    }
    return true;
}

}  // namespace driftlab::rig
