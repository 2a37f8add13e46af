#pragma once
// A diagnosis as the store and scripts keep it: the JSON of `driftlab-cli
// diagnose --json`, and the model fit an adopted extension is kept as. Shared
// by the CLI and the GUI's Diagnosis page.

#include <QJsonObject>
#include <optional>

#include "core/diagnosis/Diagnosis.h"
#include "db/DiagnosisStore.h"
#include "db/ModelFitStore.h"

namespace driftlab::db {

/// The base model every diagnosis extends, as stored.
inline const QString kDiagnosisBaseModel = QStringLiteral("screw-fdm");

/// One finding: cause, step, confidence, parameters ± σ, ΔBIC, evidence and
/// its held-out gain on its quantity, with both quantities before and after.
QJsonObject findingJson(const diagnosis::Finding& finding);

/// The whole result: runs, base figures, findings, the causes adopted in
/// order, verdict (and its evidence), what remains.
QJsonObject diagnosisJson(const diagnosis::DiagnosisResult& result);

/// The model fit an adopted extension is kept as: "heat-transfer+CAUSE" on the
/// diagnosis's runs, its parameters, its held-out gain as metrics.
ModelFitRecord adoptedExtensionFit(const diagnosis::DiagnosisResult& result,
                                   const diagnosis::Finding& finding);

/// Stores the extension `finding` as a model fit and returns its id; with
/// `diagnosisId`, that stored diagnosis records it as its adopted fit. One
/// transaction; nullopt with `error` (nothing stored then).
std::optional<qint64> adoptExtension(CampaignStore& store, qint64 campaignId,
                                     const diagnosis::DiagnosisResult& result,
                                     const diagnosis::Finding& finding,
                                     std::optional<qint64> diagnosisId, QString* error);

/// The models of the extensions adopted in campaign `campaignId`
/// ("heat-transfer+motor_heat"), newest first, each once: what live
/// compensation can step besides heat-transfer.
QStringList adoptedExtensionModels(CampaignStore& store, qint64 campaignId);

}  // namespace driftlab::db
