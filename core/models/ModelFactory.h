#pragma once
// Models by name, as the CLI (`fit --model NAME`) and the GUI ask for them.

#include <QString>
#include <QStringList>
#include <memory>

#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

/// The names makeModel knows, in the order a comparison lists them.
QStringList modelNames();

/// The families a comparison tries on a target: for a drift channel all but
/// `heat-transfer` (it predicts the screw's positioning error); for a
/// positioning error (`target` empty) all but the spindle-heat families
/// (`lsall-heat`, `ridge-heat`, `pcr-heat`: they model a spindle's drift).
QStringList modelNamesFor(const QString& target);

/// The names a single fit can ask for: the families, "auto", which chooses
/// among them by cross-validation on the training runs (AutoModel), and
/// "none", no compensation (NoCompensationModel).
QStringList fitModelNames();

/// A model with default options, or nullptr for an unknown name.
std::unique_ptr<ThermalErrorModel> makeModel(const QString& name);

}  // namespace driftlab::models
