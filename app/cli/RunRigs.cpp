#include "app/cli/RunRigs.h"

#include "acquisition/engine/SimulatedRig.h"
#include "app/cli/CliCommon.h"
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

}  // namespace

QList<QCommandLineOption> rigOptions() {
    return {kSeed, kEffect};
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
    throw CliError(QStringLiteral("--rig: '%1' is not a rig (sim, modbus://HOST:PORT)").arg(rig),
                   2);
}

}  // namespace driftlab::cli
