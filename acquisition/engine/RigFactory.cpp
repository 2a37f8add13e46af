#include "acquisition/engine/RigFactory.h"

#include <QUrl>

#include "acquisition/engine/DeviceRig.h"
#include "acquisition/engine/SimulatedRig.h"
#include "core/procedures/ProcedurePlan.h"
#include "core/rig/ModuleOutage.h"
#include "core/rig/RigEffects.h"

namespace driftlab::engine {
namespace {

std::nullptr_t fail(RigError* error, const QString& option, const QString& message) {
    if (error) *error = {option, message};
    return nullptr;
}

/// The module outages of a simulated run of `procedure`, each in one of its
/// runs; nullopt with `error` on a bad one.
std::optional<std::vector<rig::ModuleOutage>> moduleOutages(const RigOptions& options,
                                                            const procedures::Procedure& procedure,
                                                            RigError* error) {
    std::vector<rig::ModuleOutage> outages;
    if (options.outages.isEmpty()) return outages;
    const QString option = QStringLiteral("outage");
    if (procedure.on_device_loss == procedures::DeviceLossPolicy::Pause) {
        fail(error, option,
             QStringLiteral("procedure '%1' pauses on a lost device (on_device_loss: pause); "
                            "the simulated rig logs through an outage, as with continue")
                 .arg(procedure.name));
        return std::nullopt;
    }
    std::vector<procedures::PlannedRun> planned;
    try {
        planned = procedures::planRuns(procedure);
    } catch (const std::exception& e) {
        fail(error, option, QStringLiteral("procedure '%1': %2").arg(procedure.name, e.what()));
        return std::nullopt;
    }
    QStringList ids;
    for (const auto& run : planned) ids << run.id;
    for (const QString& text : options.outages) {
        QString why;
        const auto outage = rig::parseModuleOutage(text, &why);
        if (!outage) {
            fail(error, option, why);
            return std::nullopt;
        }
        const auto run = std::find_if(planned.begin(), planned.end(),
                                      [&](const auto& r) { return r.id == outage->run_id; });
        if (run == planned.end()) {
            fail(error, option,
                 QStringLiteral("'%1': procedure '%2' has no run '%3' (its runs: %4)")
                     .arg(text, procedure.name, outage->run_id, ids.join(QStringLiteral(", "))));
            return std::nullopt;
        }
        if (outage->from_s >= run->duration_s) {
            fail(error, option,
                 QStringLiteral("'%1': run %2 ends at %3 s, before the outage starts")
                     .arg(text, run->id)
                     .arg(run->duration_s));
            return std::nullopt;
        }
        outages.push_back(*outage);
    }
    return outages;
}

std::unique_ptr<TestRig> makeDeviceRig(const RigOptions& options, RigError* error) {
    QString why;
    if (!options.outages.isEmpty())
        return fail(error, QStringLiteral("outage"),
                    QStringLiteral("for the simulated rig (--rig sim); a real module's "
                                   "outages are its own"));
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
    if (!(options.connect_timeout_s > 0))
        return fail(error, QStringLiteral("connect-timeout-s"),
                    QStringLiteral("must be a positive number of seconds"));
    spec.connect_timeout_s = options.connect_timeout_s;
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

std::optional<devices::InterferometerStreamOptions> parseInterferometerUrl(const QString& text,
                                                                           QString* error) {
    const QUrl url(text, QUrl::StrictMode);
    if (!url.isValid() || url.scheme() != QLatin1String("tcp") || url.host().isEmpty() ||
        url.port() <= 0 || (!url.path().isEmpty() && url.path() != QLatin1String("/"))) {
        if (error) *error = QStringLiteral("'%1' is not tcp://HOST:PORT").arg(text);
        return std::nullopt;
    }
    devices::InterferometerStreamOptions options;
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
        auto outages = moduleOutages(options, procedure, error);
        if (!outages) return nullptr;
        spec.module_outages = std::move(*outages);
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
