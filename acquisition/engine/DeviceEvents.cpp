#include "acquisition/engine/DeviceEvents.h"

namespace driftlab::engine {

QString temperatureModuleSource(const QString& endpoint) {
    return QStringLiteral("temperature module %1").arg(endpoint);
}

SourceEvent deviceLostEvent(const QString& source, const QString& reason) {
    return {QStringLiteral("error"), source, reason};
}

SourceEvent deviceBackEvent(const QString& source, const QString& from, const QString& to,
                            double seconds) {
    return {QStringLiteral("warning"), source,
            QStringLiteral("gap: no data from %1 to %2 (%3 s); reconnected")
                .arg(from, to)
                .arg(seconds)};
}

}  // namespace driftlab::engine
