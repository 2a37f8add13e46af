#pragma once
// The rigs `run` can drive, from its --rig and rig options.

#include <QCommandLineParser>
#include <memory>

#include "acquisition/engine/TestRig.h"
#include "core/procedures/Procedure.h"

namespace driftlab::cli {

/// Options of the rigs: --seed, --effect (simulated), --device-map (Modbus).
QList<QCommandLineOption> rigOptions();
/// The rig `rig` names; throws CliError (exit 2) on a bad name or option.
std::unique_ptr<engine::TestRig> makeRig(const QCommandLineParser& parser, const QString& rig,
                                         const procedures::Procedure& procedure);

}  // namespace driftlab::cli
