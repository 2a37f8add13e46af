#pragma once
// Models by name, as the CLI (`fit --model NAME`) and the GUI ask for them.

#include <QString>
#include <QStringList>
#include <memory>

#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

/// The names makeModel knows, in the order a comparison lists them.
QStringList modelNames();

/// A model with default options, or nullptr for an unknown name.
std::unique_ptr<ThermalErrorModel> makeModel(const QString& name);

}  // namespace driftlab::models
