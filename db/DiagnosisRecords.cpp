#include "db/DiagnosisRecords.h"

#include <QJsonArray>

#include "db/ModelFitRecords.h"
#include "db/ModelTrustJson.h"

namespace driftlab::db {

QJsonObject findingJson(const diagnosis::Finding& f) {
    QJsonObject parameters, sigmas;
    for (const auto& [name, p] : f.parameters) {
        parameters[name] = jsonNumber(p.value);
        sigmas[name] = jsonNumber(p.sigma);
    }
    const QString unit =
        f.gain.unit == QLatin1String("K") ? QStringLiteral("K") : QStringLiteral("um");
    return {
        {QStringLiteral("cause"), f.cause},
        {QStringLiteral("step"), f.step},
        {QStringLiteral("confidence"), jsonNumber(f.confidence)},
        {QStringLiteral("significant"), f.significant},
        {QStringLiteral("parameters"), parameters},
        {QStringLiteral("sigma"), sigmas},
        {QStringLiteral("bic_drop"), jsonNumber(f.bic_drop)},
        {QStringLiteral("evidence"), f.evidence},
        {QStringLiteral("gain"),
         QJsonObject{
             {QStringLiteral("quantity"), f.gain.quantity},
             {QStringLiteral("test_rms_before_") + unit, jsonNumber(f.gain.test_rms_before)},
             {QStringLiteral("test_rms_after_") + unit, jsonNumber(f.gain.test_rms_after)},
             {QStringLiteral("reduction"), jsonNumber(f.gain.reduction)},
             {QStringLiteral("positioning_rms_before_um"), jsonNumber(f.test_before.error_rms_um)},
             {QStringLiteral("positioning_rms_after_um"), jsonNumber(f.test_after.error_rms_um)},
             {QStringLiteral("temperature_rms_before_K"),
              jsonNumber(f.test_before.temperature_rms_K)},
             {QStringLiteral("temperature_rms_after_K"),
              jsonNumber(f.test_after.temperature_rms_K)}}}};
}

QJsonObject diagnosisJson(const diagnosis::DiagnosisResult& r) {
    QJsonArray findings, causes;
    for (const auto& f : r.findings) findings << findingJson(f);
    for (const QString& cause : r.causes)
        if (const auto* f = diagnosis::adoptedFinding(r, cause))
            causes << QJsonObject{{QStringLiteral("cause"), cause},
                                  {QStringLiteral("step"), f->step},
                                  {QStringLiteral("confidence"), jsonNumber(f->confidence)},
                                  {QStringLiteral("quantity"), f->gain.quantity},
                                  {QStringLiteral("reduction"), jsonNumber(f->gain.reduction)}};
    QJsonObject json{
        {QStringLiteral("base_model"), kDiagnosisBaseModel},
        {QStringLiteral("train_runs"), QJsonArray::fromStringList(r.train_runs)},
        {QStringLiteral("test_runs"), QJsonArray::fromStringList(r.test_runs)},
        {QStringLiteral("base"),
         QJsonObject{
             {QStringLiteral("test_rms_um"), jsonNumber(r.base_test.error_rms_um)},
             {QStringLiteral("test_peak_um"), jsonNumber(r.base_test.error_peak_um)},
             {QStringLiteral("test_temperature_rms_K"), jsonNumber(r.base_test.temperature_rms_K)},
             {QStringLiteral("reading_noise_um"), jsonNumber(r.base_test.error_noise_um)}}},
        {QStringLiteral("findings"), findings},
        {QStringLiteral("causes"), causes},
        {QStringLiteral("verdict"), r.verdict},
        {QStringLiteral("gaps"), gapsJson(r.gaps)}};
    if (!r.verdict_evidence.isEmpty())
        json[QStringLiteral("verdict_evidence")] = r.verdict_evidence;
    if (!r.remaining.isEmpty()) json[QStringLiteral("remaining")] = r.remaining;
    if (!r.causes.isEmpty())
        json[QStringLiteral("structure_explained")] = jsonNumber(r.structure_explained);
    return json;
}

ModelFitRecord adoptedExtensionFit(const diagnosis::DiagnosisResult& r,
                                   const diagnosis::Finding& f) {
    return {
        0,
        QStringLiteral("heat-transfer+") +
            (f.step > 1 && !r.causes.isEmpty() ? r.causes.front() + QLatin1Char('+') : QString()) +
            f.cause,
        QStringLiteral("positioning"),
        r.train_runs,
        r.test_runs,
        parametersJson(f.fit.parameters),
        findingJson(f)[QStringLiteral("gain")].toObject()};
}

std::optional<qint64> adoptExtension(CampaignStore& store, qint64 campaignId,
                                     const diagnosis::DiagnosisResult& result,
                                     const diagnosis::Finding& finding,
                                     std::optional<qint64> diagnosisId, QString* error) {
    QSqlDatabase& db = store.database();
    if (!db.transaction()) {
        *error = QStringLiteral("%1: cannot start a transaction to adopt '%2'")
                     .arg(store.path(), finding.cause);
        return std::nullopt;
    }
    auto fitId = storeModelFit(store, campaignId, adoptedExtensionFit(result, finding), error);
    if (fitId && diagnosisId && !setAdoptedFit(store, *diagnosisId, *fitId, error)) fitId.reset();
    if (!fitId || !db.commit()) {
        if (fitId) *error = QStringLiteral("%1: cannot commit the adopted fit").arg(store.path());
        db.rollback();
        return std::nullopt;
    }
    return fitId;
}

QStringList adoptedExtensionModels(CampaignStore& store, qint64 campaignId) {
    const QString prefix = QStringLiteral("heat-transfer+");
    QStringList models;
    const std::vector<ModelFitRecord> fits = modelFits(store, campaignId);
    for (auto fit = fits.rbegin(); fit != fits.rend(); ++fit)
        if (fit->model.startsWith(prefix) && !models.contains(fit->model)) models << fit->model;
    return models;
}

}  // namespace driftlab::db
