#include "db/ModelFitRecords.h"

#include <cmath>

namespace driftlab::db {

QJsonValue jsonNumber(double value) {
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue();
}

QJsonObject parametersJson(const std::map<QString, models::Parameter>& parameters) {
    QJsonObject json;
    for (const auto& [name, p] : parameters)
        json[name] = QJsonObject{{QStringLiteral("value"), jsonNumber(p.value)},
                                 {QStringLiteral("sigma"), jsonNumber(p.sigma)},
                                 {QStringLiteral("unit"), p.unit}};
    return json;
}

QJsonObject scoreJson(const models::Score& score) {
    return {{QStringLiteral("rms_um"), jsonNumber(score.rms_um)},
            {QStringLiteral("peak_um"), jsonNumber(score.peak_um)},
            {QStringLiteral("reduction"), jsonNumber(score.reduction)},
            {QStringLiteral("uncompensated_rms_um"), jsonNumber(score.uncompensated_rms_um)}};
}

ModelFitRecord modelFitRecord(const QString& model, const QString& targetChannel,
                              const QStringList& trainRuns, const QStringList& testRuns,
                              const models::FitSummary& fit, const models::Score& score) {
    QJsonObject metrics;
    for (const auto& [name, value] : fit.metrics) metrics[name] = jsonNumber(value);
    metrics[QStringLiteral("train_rms_um")] = jsonNumber(fit.rms_um);
    metrics[QStringLiteral("iterations")] = fit.iterations;
    const bool heldOut = !testRuns.isEmpty();
    metrics[QStringLiteral("score_kind")] =
        heldOut ? QStringLiteral("held_out") : QStringLiteral("training");
    metrics[heldOut ? QStringLiteral("test") : QStringLiteral("training")] = scoreJson(score);
    return {0,
            model,
            targetChannel.isEmpty() ? QStringLiteral("positioning") : targetChannel,
            trainRuns,
            testRuns,
            parametersJson(fit.parameters),
            metrics};
}

}  // namespace driftlab::db
