#include "db/BatchAnalysis.h"

#include <QJsonArray>
#include <stdexcept>
#include <utility>

#include "core/diagnosis/Diagnosis.h"
#include "core/domain/ServiceError.h"
#include "core/iso/Iso230_2.h"
#include "core/iso/PositioningRuns.h"
#include "core/models/ModelledRuns.h"
#include "db/AnalysisJson.h"
#include "db/DiagnosisRecords.h"
#include "db/HeldOutFit.h"

namespace driftlab::db {
namespace {

/// The model batch fits: the one that should carry across moving states (docs/models.md).
const QString kBatchModel = QStringLiteral("heat-transfer");

/// `iso230-2 --json`'s axis values for the default positioning run, without
/// the per-target detail; null when the campaign has no single such run.
QJsonValue iso230Result(const Campaign& campaign, QJsonObject& skipped) {
    const iso::DefaultRun chosen = iso::defaultPositioningRun(campaign);
    if (chosen.id.isEmpty()) {
        skipped[analysisKey(kAnalysisIso230_2)] = chosen.why;
        return QJsonValue();
    }
    const iso::PositioningRunChoice choice = iso::choosePositioningRun(campaign, chosen.id);
    if (!choice.run) throw ServiceError(choice.error);
    const Run& run = *choice.run;
    const iso::Evaluation result = iso::evaluate(iso::readingsOf(run), iso::Settings{});
    if (!result.ok()) throw ServiceError(QStringLiteral("run %1: %2").arg(run.id, result.error));
    QJsonObject json = iso230EvaluationJson(result);
    json.remove(QStringLiteral("targets"));
    json[QStringLiteral("run")] = run.id;
    return json;
}

/// `fit --model heat-transfer --json`: trained on the first feed-axis run,
/// scored on the others; without how long the fit took (its message and
/// identification_s), so that two batches of the same campaigns give the same
/// lines (the item's own "seconds" says how long it took).
QJsonValue fitResult(const Campaign& campaign, const BatchAnalysisOptions& options) {
    HeldOutFitOptions fitOptions;
    fitOptions.model = kBatchModel;
    fitOptions.cancelled = options.cancelled;
    QJsonObject json = fitHeldOut(campaign, fitOptions).json();
    QJsonObject fit = json[QStringLiteral("fit")].toObject();
    QJsonObject metrics = fit[QStringLiteral("metrics")].toObject();
    metrics.remove(QStringLiteral("identification_s"));
    fit[QStringLiteral("metrics")] = metrics;
    fit.remove(QStringLiteral("message"));
    json[QStringLiteral("fit")] = fit;
    return json;
}

/// `diagnose --json` in short: runs, the base model's held-out figures, each
/// finding's cause, confidence and held-out reduction, the verdict.
QJsonValue diagnosisResult(const Campaign& campaign, const BatchAnalysisOptions& options) {
    diagnosis::DiagnosisOptions diagnosisOptions;
    if (options.cancelled) diagnosisOptions.progress = [&](double) { return !options.cancelled(); };
    const diagnosis::DiagnosisResult r = diagnosis::diagnose(campaign, diagnosisOptions);
    if (!r.ok()) throw ServiceError(r.error);
    const QJsonObject full = diagnosisJson(r);
    const QJsonObject base = full[QStringLiteral("base")].toObject();
    QJsonArray findings;
    for (const QJsonValue& f : full[QStringLiteral("findings")].toArray())
        findings << QJsonObject{
            {QStringLiteral("cause"), f[QStringLiteral("cause")]},
            {QStringLiteral("confidence"), f[QStringLiteral("confidence")]},
            {QStringLiteral("significant"), f[QStringLiteral("significant")]},
            {QStringLiteral("reduction"), f[QStringLiteral("gain")][QStringLiteral("reduction")]}};
    return QJsonObject{
        {QStringLiteral("train_runs"), full[QStringLiteral("train_runs")]},
        {QStringLiteral("test_runs"), full[QStringLiteral("test_runs")]},
        {QStringLiteral("base"),
         QJsonObject{{QStringLiteral("test_rms_um"), base[QStringLiteral("test_rms_um")]},
                     {QStringLiteral("test_peak_um"), base[QStringLiteral("test_peak_um")]}}},
        {QStringLiteral("findings"), findings},
        {QStringLiteral("verdict"), full[QStringLiteral("verdict")]}};
}

}  // namespace

QStringList batchAnalyses() {
    return {kAnalysisInfo, kAnalysisIso230_2, kAnalysisFit, kAnalysisDiagnose};
}

QString analysisKey(const QString& analysis) {
    if (analysis == kAnalysisIso230_2) return QStringLiteral("iso230_2");
    if (analysis == kAnalysisDiagnose) return QStringLiteral("diagnosis");
    return analysis;
}

BatchAnalysis analyseCampaign(const Campaign& campaign, const BatchAnalysisOptions& options) {
    const QStringList& what = options.analyses;
    const QJsonObject info = campaignInfoJson(campaign);
    BatchAnalysis out;
    QJsonObject& result = out.json;
    result = {{QStringLiteral("name"), info[QStringLiteral("name")]},
              {QStringLiteral("runs"), info[QStringLiteral("runs")]}};
    if (what.contains(kAnalysisInfo))
        for (const char* key : {"machine", "axis", "channels"})
            result[QLatin1String(key)] = info[QLatin1String(key)];

    QJsonObject skipped;
    // The models need a feed-axis run with positioning readings; a spindle or
    // ETVE campaign has none, which is no failure of the campaign.
    const bool modelled = !models::modelledRuns(campaign).isEmpty();
    const QString noModelledRun = QStringLiteral(
        "no feed-axis run with positioning readings from a cold reference (cycle 0)");
    const std::pair<QString, std::function<QJsonValue()>> analyses[] = {
        {kAnalysisIso230_2, [&] { return iso230Result(campaign, skipped); }},
        {kAnalysisFit, [&] { return fitResult(campaign, options); }},
        {kAnalysisDiagnose, [&] { return diagnosisResult(campaign, options); }}};
    double done = 0;
    for (const auto& [name, run] : analyses) {
        if (!what.contains(name)) continue;
        if (options.cancelled && options.cancelled()) {
            out.cancelled = true;
            break;
        }
        if (options.progress) options.progress(name, done++ / double(what.size()));
        const QString key = analysisKey(name);
        result[key] = QJsonValue();
        if (name != kAnalysisIso230_2 && !modelled) {
            skipped[key] = noModelledRun;
            continue;
        }
        try {
            result[key] = run();
        } catch (const std::runtime_error& e) {
            out.errors << QStringLiteral("%1: %2").arg(name, QString::fromStdString(e.what()));
        }
    }
    out.cancelled |= options.cancelled && options.cancelled();
    if (!skipped.isEmpty()) result[QStringLiteral("skipped")] = skipped;
    if (!out.errors.isEmpty())
        result[QStringLiteral("error")] = out.errors.join(QStringLiteral("; "));
    return out;
}

}  // namespace driftlab::db
