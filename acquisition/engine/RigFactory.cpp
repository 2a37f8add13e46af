#include "acquisition/engine/RigFactory.h"

#include <QUrl>

#include "acquisition/engine/DeviceRig.h"
#include "acquisition/engine/SimulatedRig.h"
#include "core/rig/RigEffects.h"

namespace driftlab::engine {
namespace {

std::nullptr_t fail(RigError* error, const QString& option, const QString& message) {
    if (error) *error = {option, message};
    return nullptr;
}

std::unique_ptr<TestRig> makeDeviceRig(const RigOptions& options, RigError* error) {
    QString why;
    DeviceRigSpec spec;
    const auto url = modbus::parseModbusUrl(options.rig, &why);
    if (!url) return fail(error, QStringLiteral("rig"), why);
    spec.temperature_url = *url;
    if (options.device_map_path.isEmpty())
        return fail(error, QStringLiteral("device-map"),
                    QStringLiteral("the Modbus rig %1 needs the module's register map (a JSON "
                                   "file, e.g. resources/devices/temperature-8ch-pt100.json)")
                        .arg(options.rig));
    const auto map = devices::loadChannelRegisterMap(options.device_map_path, &why);
    if (!map) return fail(error, QStringLiteral("device-map"), why);
    spec.temperature_map = *map;
    if (!(options.poll_interval_s > 0))
        return fail(error, QStringLiteral("poll-interval-s"), QStringLiteral("must be positive"));
    spec.poll_interval_s = options.poll_interval_s;
    if (!options.controller_url.isEmpty()) {
        spec.controller_url = modbus::parseModbusUrl(options.controller_url, &why);
        if (!spec.controller_url) return fail(error, QStringLiteral("controller"), why);
    }
    if (!options.interferometer_url.isEmpty()) {
        spec.interferometer = parseInterferometerUrl(options.interferometer_url, &why);
        if (!spec.interferometer) return fail(error, QStringLiteral("interferometer"), why);
    }
    if (!(options.target_tolerance_mm > 0))
        return fail(error, QStringLiteral("target-tolerance-mm"),
                    QStringLiteral("must be positive"));
    spec.target_tolerance_mm = options.target_tolerance_mm;
    spec.campaign_template = options.machine;
    return std::make_unique<DeviceRig>(spec);
}

}  // namespace

std::optional<InterferometerStreamOptions> parseInterferometerUrl(const QString& text,
                                                                  QString* error) {
    const QUrl url(text, QUrl::StrictMode);
    if (!url.isValid() || url.scheme() != QLatin1String("tcp") || url.host().isEmpty() ||
        url.port() <= 0 || (!url.path().isEmpty() && url.path() != QLatin1String("/"))) {
        if (error) *error = QStringLiteral("'%1' is not tcp://HOST:PORT").arg(text);
        return std::nullopt;
    }
    InterferometerStreamOptions options;
    options.host = url.host();
    options.port = quint16(url.port());
    return options;
}

std::unique_ptr<TestRig> makeRig(const RigOptions& options, const procedures::Procedure& procedure,
                                 RigError* error) {
    if (options.rig == QLatin1String("sim")) {
        rig::RigSpec spec;
        spec.seed = options.seed;
        for (const QString& assignment : options.effects) {
            QString why;
            if (!rig::applyEffect(spec.effects, assignment, &why))
                return fail(error, QStringLiteral("effect"), why);
        }
        spec.campaign_name = procedure.name;
        spec.travel_mm = procedure.travel_mm;
        spec.sample_interval_s = procedure.sample_interval_s;
        return std::make_unique<SimulatedRig>(spec);
    }
    if (options.rig.startsWith(QLatin1String("modbus://")) ||
        options.rig.startsWith(QLatin1String("modbus-rtu://")))
        return makeDeviceRig(options, error);
    return fail(error, QStringLiteral("rig"),
                QStringLiteral("'%1' is not a rig (sim, modbus://HOST:PORT)").arg(options.rig));
}

}  // namespace driftlab::engine
