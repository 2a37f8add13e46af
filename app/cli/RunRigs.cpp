#include "app/cli/RunRigs.h"

#include <QFile>

#include "acquisition/engine/RigFactory.h"
#include "app/cli/CliCommon.h"
#include "core/bundle/BundleError.h"
#include "core/bundle/CampaignJson.h"

namespace driftlab::cli {
namespace {

const QCommandLineOption kSeed{QStringLiteral("seed"),
                               QStringLiteral("Simulated rig: random seed (noise, room)."),
                               QStringLiteral("N"), QStringLiteral("1")};
const QCommandLineOption kEffect{
    QStringLiteral("effect"),
    QStringLiteral("Simulated rig: hide an effect, ID=VALUE (as `simulate --effect`)."),
    QStringLiteral("ID=VALUE")};
const QCommandLineOption kOutage{
    QStringLiteral("outage"),
    QStringLiteral("Simulated rig: the temperature module does not answer in run RUN from FROM "
                   "to TO s of run time (repeatable; as `simulate --outage`)."),
    QStringLiteral("RUN@FROM-TO")};

const QCommandLineOption kDeviceMap{
    QStringLiteral("device-map"),
    QStringLiteral("Modbus rig: the temperature module's register map (JSON, e.g. "
                   "/usr/share/driftlab/devices/temperature-8ch-pt100.json when installed, "
                   "resources/devices/ in the source)."),
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
const QCommandLineOption kConnectTimeout{
    QStringLiteral("connect-timeout-s"),
    QStringLiteral("Modbus rig: how long the module and the controller may take to give their "
                   "first reading before the run fails (s)."),
    QStringLiteral("S"), QStringLiteral("30")};

}  // namespace

QList<QCommandLineOption> rigOptions() {
    return {kSeed,           kEffect,    kOutage,  kDeviceMap, kController,
            kInterferometer, kTolerance, kMachine, kPoll,      kConnectTimeout};
}

std::unique_ptr<engine::TestRig> makeRig(const QCommandLineParser& parser, const QString& rig,
                                         const procedures::Procedure& procedure) {
    engine::RigOptions options;
    options.rig = rig;
    bool ok = false;
    options.seed = parser.value(kSeed).toUInt(&ok);
    if (!ok) throw CliError(QStringLiteral("--seed: not a non-negative integer"), 2);
    options.effects = parser.values(kEffect);
    options.outages = parser.values(kOutage);
    options.device_map_path = parser.value(kDeviceMap);
    options.controller_url = parser.value(kController);
    options.interferometer_url = parser.value(kInterferometer);
    if (options.rig != QLatin1String("sim")) {
        options.target_tolerance_mm = positiveNumberOption(parser, kTolerance);
        options.poll_interval_s = positiveNumberOption(parser, kPoll);
        options.connect_timeout_s = positiveNumberOption(parser, kConnectTimeout);
    }
    if (parser.isSet(kMachine)) {
        QFile file(parser.value(kMachine));
        if (!file.open(QIODevice::ReadOnly))
            throw CliError(
                QStringLiteral("--machine: %1: %2").arg(file.fileName(), file.errorString()), 2);
        try {
            options.machine = bundle::campaignFromJson(file.readAll(), file.fileName());
        } catch (const bundle::BundleError& e) {
            throw CliError(QStringLiteral("--machine: %1").arg(e.toString()), 2);
        }
    }
    engine::RigError error;
    auto made = engine::makeRig(options, procedure, &error);
    if (!made) throw CliError(QStringLiteral("--") + error.toString(), 2);
    return made;
}

}  // namespace driftlab::cli
