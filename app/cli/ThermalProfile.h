#pragma once
// The thermal part of a compensation table: a model fitted on training runs,
// evaluated at a stated state (a run and a time in it) over the axis. Shared
// by `compensate` (table = cold error + this) and the straight-line
// temperature compensation formats.

#include <QCommandLineParser>

#include "core/compensation/CompensationTable.h"
#include "core/domain/Campaign.h"
#include "core/models/ModelValidation.h"

namespace driftlab::cli {

struct ThermalProfile {
    compensation::ErrorProfile error_um;  ///< actual − target, µm, at a position
    /// The 95 % half-width of the model's prediction interval, µm, at a position.
    compensation::ErrorProfile uncertainty_um;
    models::Validation validation;  ///< the model's cross-validation on its training runs
    QString description;            ///< "heat-transfer fitted on S1, at S3 t = 3600 s"
    double from_mm = 0, to_mm = 0;  ///< where it was evaluated
    double fixed_end_mm = 0;        ///< the screw's fixed end (0 without a screw)
};

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
