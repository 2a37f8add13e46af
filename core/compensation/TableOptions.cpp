#include "core/compensation/TableOptions.h"

namespace driftlab::compensation {

QString signName(ValueSign sign) {
    return sign == ValueSign::Correction ? QStringLiteral("correction") : QStringLiteral("error");
}

QString modeName(ValueMode mode) {
    return mode == ValueMode::Absolute ? QStringLiteral("absolute") : QStringLiteral("incremental");
}

std::optional<ValueSign> parseSign(const QString& name) {
    if (name == QLatin1String("correction")) return ValueSign::Correction;
    if (name == QLatin1String("error")) return ValueSign::Error;
    return std::nullopt;
}

std::optional<ValueMode> parseMode(const QString& name) {
    if (name == QLatin1String("absolute")) return ValueMode::Absolute;
    if (name == QLatin1String("incremental")) return ValueMode::Incremental;
    return std::nullopt;
}

}  // namespace driftlab::compensation
