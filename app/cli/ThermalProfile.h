#pragma once
// The options of the thermal part of a compensation table (--model, --train,
// --at) for `compensate` and the straight-line temperature compensation
// formats; the work is core/compensation/ThermalProfile's, shared with the GUI.

#include <QCommandLineParser>

#include "core/compensation/ThermalProfile.h"
#include "core/domain/Campaign.h"
#include "core/models/ModelValidation.h"

namespace driftlab::cli {

using compensation::ThermalProfile;

/// --model, --train, --at, --force.
QList<QCommandLineOption> thermalProfileOptions();

/// --force: use a model that does worse than no compensation on its own
/// cross-validation (shared with `live`).
const QCommandLineOption& forceOption();

/// Refuses (CliError) a model worse than no compensation on its own
/// cross-validation unless --force is given, then only warns; `what` names it.
void refuseHarm(const QCommandLineParser& parser, const models::Validation& validation,
                const QString& what);

/// True when --model or --at was given (both are then required).
bool wantsThermalProfile(const QCommandLineParser& parser);

/// Fits and validates the model and evaluates it at the state over
/// [from_mm, to_mm]. Throws CliError naming the option at fault, and for a
/// model worse than no compensation without --force (refuseHarm).
ThermalProfile thermalProfile(const QCommandLineParser& parser, const Campaign& campaign,
                              double from_mm, double to_mm);

/// The formats that take a line, not a table: `sinumerik-temp`, `isg-temp`.
bool isTemperatureLineFormat(const QString& format);

/// Writes the least-squares line of the profile over its range as `format`
/// to --out (reference: --reference, default the screw's fixed end) and
/// prints its summary; returns the exit code.
int writeTemperatureLine(const QCommandLineParser& parser, const ThermalProfile& profile,
                         const QString& format, const QString& source);

}  // namespace driftlab::cli
