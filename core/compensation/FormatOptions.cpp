#include "core/compensation/FormatOptions.h"

#include <algorithm>

namespace driftlab::compensation {
namespace {

template <typename T>
bool holds(const std::vector<T>& options, T option) {
    return std::find(options.begin(), options.end(), option) != options.end();
}

}  // namespace

FormatOptions formatOptions(const QString& format) {
    using S = ValueSign;
    using M = ValueMode;
    FormatOptions o;
    if (format == QLatin1String("csv")) {
        // DriftLab's own table: anything an integrator's script asks for.
        o = {{S::Correction, S::Error}, {M::Absolute, M::Incremental}, true, {}, {}, {}};
    } else if (format == QLatin1String("linuxcnc")) {
        o = {{S::Error},
             {M::Absolute},
             true,
             QStringLiteral("COMP_FILE_TYPE 0 holds the actual positions, nominal + error (the "
                            "correction is COMP_FILE_TYPE 1, --format linuxcnc-type1)"),
             QStringLiteral("LinuxCNC interpolates absolute values between its entries"),
             {}};
    } else if (format == QLatin1String("linuxcnc-type1")) {
        o = {{S::Correction},
             {M::Absolute},
             true,
             QStringLiteral("COMP_FILE_TYPE 1 holds the trims LinuxCNC adds to the motor "
                            "command, the correction (the error is COMP_FILE_TYPE 0, "
                            "--format linuxcnc)"),
             QStringLiteral("LinuxCNC interpolates absolute values between its entries"),
             {}};
    } else if (format == QLatin1String("fanuc") || format == QLatin1String("fanuc-g10")) {
        o = {{S::Correction},
             {M::Incremental},
             false,
             QStringLiteral("Fanuc adds the compensation pulses to the move"),
             QStringLiteral("Fanuc pitch error data are increments between compensation points"),
             QStringLiteral("bidirectional pitch error data (3605#0, 3626, 3627) are not "
                            "written; the backlash goes to parameter 1851")};
    } else if (format == QLatin1String("sinumerik")) {
        o = {{S::Error},
             {M::Absolute},
             false,
             QStringLiteral("Sinumerik corrects the actual value: a positive compensation value "
                            "moves the axis in the negative direction"),
             QStringLiteral("$AA_ENC_COMP holds absolute values at each point"),
             QStringLiteral("direction-dependent compensation is a separate table type, not "
                            "written; the backlash goes to MD32450 $MA_BACKLASH")};
    } else if (format == QLatin1String("heidenhain")) {
        // The public documentation does not settle the sign: both can be written.
        o = {{S::Correction, S::Error},
             {M::Absolute},
             true,
             {},
             QStringLiteral("a .COM table holds absolute values at each AXISPOS"),
             {}};
    }
    return o;
}

ValueSign effectiveSign(const QString& format, std::optional<ValueSign> sign) {
    const FormatOptions o = formatOptions(format);
    return sign ? *sign : o.signs.empty() ? ValueSign::Correction : o.signs.front();
}

ValueMode effectiveMode(const QString& format, std::optional<ValueMode> mode) {
    const FormatOptions o = formatOptions(format);
    return mode ? *mode : o.modes.empty() ? ValueMode::Absolute : o.modes.front();
}

QString checkFormatOptions(const QString& format, std::optional<ValueSign> sign,
                           std::optional<ValueMode> mode, bool bidirectional) {
    const FormatOptions o = formatOptions(format);
    if (o.signs.empty()) return QStringLiteral("format '%1' has no table options").arg(format);
    if (sign && !holds(o.signs, *sign))
        return QStringLiteral("--sign %1: %2 holds the %3 only: %4")
            .arg(signName(*sign), format, signName(o.signs.front()), o.sign_reason);
    if (mode && !holds(o.modes, *mode))
        return QStringLiteral("--values %1: %2 holds %3 values only: %4")
            .arg(modeName(*mode), format, modeName(o.modes.front()), o.mode_reason);
    if (bidirectional && !o.per_direction)
        return QStringLiteral("--bidirectional: %1 holds one combined table only: %2")
            .arg(format, o.direction_reason);
    return {};
}

}  // namespace driftlab::compensation
