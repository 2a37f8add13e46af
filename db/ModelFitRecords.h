#pragma once
// A model fit and its score as the store keeps them (table model_fit): the
// same record from `driftlab-cli fit` and from the GUI's model workbench.

#include <QJsonObject>
#include <QJsonValue>
#include <map>

#include "core/models/ModelScore.h"
#include "db/ModelFitStore.h"

namespace driftlab::db {

/// A finite number, or JSON null (NaN and infinities are not JSON).
QJsonValue jsonNumber(double value);

/// NAME: {"value", "sigma", "unit"} of every parameter.
QJsonObject parametersJson(const std::map<QString, models::Parameter>& parameters);

/// {"rms_um", "peak_um", "reduction", "uncompensated_rms_um"} of a score.
QJsonObject scoreJson(const models::Score& score);

/// The record of `fit` of model `model` on `trainRuns`, scored as `score` on
/// `testRuns` (held out) or, with no test run, on the training runs (labelled
/// "training", never where a held-out score is expected). `targetChannel`
/// empty: the positioning error.
ModelFitRecord modelFitRecord(const QString& model, const QString& targetChannel,
                              const QStringList& trainRuns, const QStringList& testRuns,
                              const models::FitSummary& fit, const models::Score& score);

}  // namespace driftlab::db
