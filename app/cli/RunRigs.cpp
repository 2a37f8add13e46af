#include "app/cli/RunRigs.h"

#include <QFile>
#include <QUrl>

#include "acquisition/engine/DeviceRig.h"
#include "acquisition/engine/SimulatedRig.h"
#include "app/cli/CliCommon.h"
#include "core/bundle/BundleError.h"
#include "core/bundle/CampaignJson.h"
#include "core/rig/RigEffects.h"

namespace driftlab::cli {
namespace {

const QCommandLineOption kSeed{QStringLiteral("seed"),
                               QStringLiteral("Simulated rig: random seed (noise, room)."),
                               QStringLiteral("N"), QStringLiteral("1")};
const QCommandLineOption kEffect{
    QStringLiteral("effect"),
    QStringLiteral("Simulated rig: hide an effect, ID=VALUE (as `simulate --effect`)."),
    QStringLiteral("ID=VALUE")};

const QCommandLineOption kDeviceMap{
    QStringLiteral("device-map"),
    QStringLiteral("Modbus rig: the temperature module's register map (JSON, e.g. "
                   "resources/devices/temperature-8ch-pt100.json)."),
    QStringLiteral("FILE")};
const QCommandLineOption kMachine{
    QStringLiteral("machine"),
    QStringLiteral("Modbus rig: a campaign.json (no runs) naming the machine, the screw and the "
                   "channels (ids as in the device map, with their roles)."),
    QStringLiteral("FILE")};
const QCommandLineOption kController{
    QStringLiteral("controller"),
    QStringLiteral("Modbus rig: the controller link (position, feed, torque, machine state; "
                   "docs/modbus-register-map.md), modbus://HOST:PORT."),
    QStringLiteral("URL")};
const QCommandLineOption kInterferometer{
    QStringLiteral("interferometer"),
    QStringLiteral("Modbus rig: the interferometer's line stream (docs/interferometer.md), "
                   "tcp://HOST:PORT; its readings are matched to the planned targets."),
    QStringLiteral("URL")};
const QCommandLineOption kTolerance{
    QStringLiteral("target-tolerance-mm"),
    QStringLiteral("Modbus rig: how far an interferometer reading may be from a planned target "
                   "to be its reading, mm."),
    QStringLiteral("MM"), QStringLiteral("0.05")};
const QCommandLineOption kPoll{QStringLiteral("poll-interval-s"),
                               QStringLiteral("Modbus rig: seconds between polls of the module."),
                               QStringLiteral("S"), QStringLiteral("1")};

InterferometerStreamOptions parseInterferometerUrl(const QString& text) {
    const QUrl url(text, QUrl::StrictMode);
    if (!url.isValid() || url.scheme() != QLatin1String("tcp") || url.host().isEmpty() ||
        url.port() <= 0 || (!url.path().isEmpty() && url.path() != QLatin1String("/")))
        throw CliError(QStringLiteral("--interferometer: '%1' is not tcp://HOST:PORT").arg(text),
                       2);
    InterferometerStreamOptions options;
    options.host = url.host();
    options.port = quint16(url.port());
    return options;
}

std::unique_ptr<engine::TestRig> makeDeviceRig(const QCommandLineParser& parser,
                                               const QString& rig) {
    QString error;
    engine::DeviceRigSpec spec;
    const auto url = modbus::parseModbusUrl(rig, &error);
    if (!url) throw CliError(QStringLiteral("--rig: ") + error, 2);
    spec.temperature_url = *url;
    if (!parser.isSet(kDeviceMap))
        throw CliError(QStringLiteral("--rig %1 needs --device-map FILE (the module's register "
                                      "map)")
                           .arg(rig),
                       2);
    const auto map = devices::loadChannelRegisterMap(parser.value(kDeviceMap), &error);
    if (!map) throw CliError(error, 2);
    spec.temperature_map = *map;
    spec.poll_interval_s = positiveNumberOption(parser, kPoll);
    if (parser.isSet(kController)) {
        spec.controller_url = modbus::parseModbusUrl(parser.value(kController), &error);
        if (!spec.controller_url) throw CliError(QStringLiteral("--controller: ") + error, 2);
    }
    if (parser.isSet(kInterferometer))
        spec.interferometer = parseInterferometerUrl(parser.value(kInterferometer));
    spec.target_tolerance_mm = positiveNumberOption(parser, kTolerance);
    if (parser.isSet(kMachine)) {
        QFile file(parser.value(kMachine));
        if (!file.open(QIODevice::ReadOnly))
            throw CliError(
                QStringLiteral("--machine: %1: %2").arg(file.fileName(), file.errorString()), 2);
        try {
            spec.campaign_template = campaignFromJson(file.readAll(), file.fileName());
        } catch (const BundleError& e) {
            throw CliError(QStringLiteral("--machine: %1").arg(e.toString()), 2);
        }
    }
    return std::make_unique<engine::DeviceRig>(spec);
}

}  // namespace

QList<QCommandLineOption> rigOptions() {
    return {kSeed, kEffect, kDeviceMap, kController, kInterferometer, kTolerance, kMachine, kPoll};
}

std::unique_ptr<engine::TestRig> makeRig(const QCommandLineParser& parser, const QString& rig,
                                         const procedures::Procedure& procedure) {
    if (rig == QLatin1String("sim")) {
        rig::RigSpec spec;
        bool ok = false;
        spec.seed = parser.value(kSeed).toUInt(&ok);
        if (!ok) throw CliError(QStringLiteral("--seed: not a non-negative integer"), 2);
        for (const QString& assignment : parser.values(kEffect)) {
            QString error;
            if (!rig::applyEffect(spec.effects, assignment, &error)) throw CliError(error, 2);
        }
        spec.campaign_name = procedure.name;
        spec.travel_mm = procedure.travel_mm;
        spec.sample_interval_s = procedure.sample_interval_s;
        return std::make_unique<engine::SimulatedRig>(spec);
    }
    if (rig.startsWith(QLatin1String("modbus://")) ||
        rig.startsWith(QLatin1String("modbus-rtu://")))
        return makeDeviceRig(parser, rig);
    throw CliError(QStringLiteral("--rig: '%1' is not a rig (sim, modbus://HOST:PORT)").arg(rig),
                   2);
}

}  // namespace driftlab::cli
