#include "acquisition/engine/DeviceProbe.h"

#include <QTcpSocket>
#include <cmath>

#include "acquisition/devices/ControllerLink.h"
#include "acquisition/devices/TemperatureModule.h"

namespace driftlab::engine {
namespace {

DeviceProbeResult probeTemperatureModule(const RigOptions& options,
                                         const sensors::SensorHealthSettings& settings,
                                         double timeout_s) {
    QString why;
    DeviceProbeResult result{QStringLiteral("temperature module %1").arg(options.rig), false, {}};
    const auto url = modbus::parseModbusUrl(options.rig, &why);
    if (!url) return {result.device, false, why};
    result.device = QStringLiteral("temperature module %1").arg(url->endpoint());
    const auto map = devices::loadChannelRegisterMap(options.device_map_path, &why);
    if (!map) return {result.device, false, QStringLiteral("device map: ") + why};
    devices::TemperatureModule module(*map, *url, timeout_s);
    if (!module.connect(&why)) return {result.device, false, why};
    const auto reading = module.read(&why);
    if (!reading) return {result.device, false, why};
    QStringList implausible, missing;
    for (std::size_t c = 0; c < reading->values.size(); ++c) {
        const double value = reading->values[c];
        const QString& id = map->channels[c].id;
        if (std::isnan(value))
            missing << id;
        else if (sensors::outOfRange(settings, Quantity::Temperature, value))
            implausible << QStringLiteral("%1 = %2").arg(id).arg(value, 0, 'f', 1);
    }
    if (!implausible.isEmpty())
        return {result.device, false,
                QStringLiteral("implausible temperatures (plausible: %1…%2 °C): %3")
                    .arg(settings.temperature_min_C)
                    .arg(settings.temperature_max_C)
                    .arg(implausible.join(QStringLiteral(", ")))};
    result.ok = true;
    result.message = QStringLiteral("%1 channels read").arg(reading->values.size());
    if (!missing.isEmpty())
        result.message +=
            QStringLiteral("; no value on %1").arg(missing.join(QStringLiteral(", ")));
    return result;
}

DeviceProbeResult probeController(const QString& text, double timeout_s) {
    QString why;
    const auto url = modbus::parseModbusUrl(text, &why);
    if (!url) return {QStringLiteral("controller %1").arg(text), false, why};
    DeviceProbeResult result{QStringLiteral("controller %1").arg(url->endpoint()), false, {}};
    devices::ControllerLink link(*url, timeout_s);
    if (!link.connect(&why)) return {result.device, false, why};
    const auto reading = link.read(&why);
    if (!reading) return {result.device, false, why};
    return {result.device, true,
            QStringLiteral("position %1 mm").arg(reading->position_mm, 0, 'f', 3)};
}

DeviceProbeResult probeInterferometer(const QString& text, double timeout_s) {
    QString why;
    const auto options = parseInterferometerUrl(text, &why);
    if (!options) return {QStringLiteral("interferometer %1").arg(text), false, why};
    DeviceProbeResult result{
        QStringLiteral("interferometer %1:%2").arg(options->host).arg(options->port), false, {}};
    // The stream protocol has no request: a connection that is accepted is the answer.
    QTcpSocket socket;
    socket.connectToHost(options->host, options->port);
    if (!socket.waitForConnected(int(timeout_s * 1000)))
        return {result.device, false, socket.errorString()};
    return {result.device, true, QStringLiteral("accepts a connection")};
}

}  // namespace

std::vector<DeviceProbeResult> probeDevices(const RigOptions& options,
                                            const sensors::SensorHealthSettings& settings,
                                            double timeout_s) {
    std::vector<DeviceProbeResult> results;
    if (options.rig == QLatin1String("sim")) return results;
    results.push_back(probeTemperatureModule(options, settings, timeout_s));
    if (!options.controller_url.isEmpty())
        results.push_back(probeController(options.controller_url, timeout_s));
    if (!options.interferometer_url.isEmpty())
        results.push_back(probeInterferometer(options.interferometer_url, timeout_s));
    return results;
}

}  // namespace driftlab::engine
