// batch-item: one campaign of `batch`, analysed in the child process that
// batch starts for it (docs/batch.md). It prints one JSON object on stdout:
// the campaign's name and runs and a key per analysis asked for. An analysis
// that does not apply to the campaign (no positioning run, no feed-axis run)
// is null and says why under "skipped"; one that fails is null, its reason is
// "error" and the exit code is 1, with the other analyses' results kept.
// Nothing is written: a store is read with a read-only connection.
#include <QJsonArray>
#include <functional>

#include "app/cli/AnalysisJson.h"
#include "app/cli/BatchItems.h"
#include "app/cli/CliCommon.h"
#include "app/cli/CommandTable.h"
#include "app/cli/FlaggedSamples.h"
#include "app/cli/HeldOutFit.h"
#include "core/diagnosis/Diagnosis.h"
#include "core/iso/PositioningRuns.h"
#include "core/models/ModelledRuns.h"
#include "db/DiagnosisRecords.h"

namespace driftlab::cli {
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
    const Run& run = choosePositioningRun(campaign, chosen.id);
    const iso::Evaluation result = iso::evaluate(iso::readingsOf(run), iso::Settings{});
    if (!result.ok()) throw CliError(QStringLiteral("run %1: %2").arg(run.id, result.error));
    QJsonObject json = iso230EvaluationJson(result);
    json.remove(QStringLiteral("targets"));
    json[QStringLiteral("run")] = run.id;
    return json;
}

/// `fit --model heat-transfer --json`: trained on the first feed-axis run,
/// scored on the others; without how long the fit took (its message and
/// identification_s), so that two batches of the same campaigns give the same
/// lines (the item's own "seconds" says how long it took).
QJsonValue fitResult(const Campaign& campaign) {
    QJsonObject json =
        fitHeldOut(campaign, kBatchModel, std::nullopt, std::nullopt, QString(), false).json();
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
QJsonValue diagnosisResult(const Campaign& campaign) {
    const diagnosis::DiagnosisResult r = diagnosis::diagnose(campaign, {});
    if (!r.ok()) throw CliError(r.error);
    const QJsonObject full = db::diagnosisJson(r);
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

int batchItemCommand(const QStringList& args) {
    QCommandLineParser parser;
    parseArguments(parser, args, campaignSourceOptions() << analysesOption() << keepFlaggedOption(),
                   campaignSourceArguments());
    const QStringList what = analysesAsked(parser);
    Campaign campaign = loadCampaignSource(parser, db::StoreAccess::ReadOnly);
    leaveOutFlaggedSamples(parser, campaign);

    const QJsonObject info = campaignInfoJson(campaign);
    QJsonObject result{{QStringLiteral("name"), info[QStringLiteral("name")]},
                       {QStringLiteral("runs"), info[QStringLiteral("runs")]}};
    if (what.contains(kAnalysisInfo))
        for (const char* key : {"machine", "axis", "channels"})
            result[QLatin1String(key)] = info[QLatin1String(key)];

    QJsonObject skipped;
    QStringList errors;
    // The models need a feed-axis run with positioning readings; a spindle or
    // ETVE campaign has none, which is no failure of the campaign.
    const bool modelled = !models::modelledRuns(campaign).isEmpty();
    const QString noModelledRun = QStringLiteral(
        "no feed-axis run with positioning readings from a cold reference (cycle 0)");
    const std::pair<QString, std::function<QJsonValue()>> analyses[] = {
        {kAnalysisIso230_2, [&] { return iso230Result(campaign, skipped); }},
        {kAnalysisFit, [&] { return fitResult(campaign); }},
        {kAnalysisDiagnose, [&] { return diagnosisResult(campaign); }}};
    for (const auto& [name, run] : analyses) {
        if (!what.contains(name)) continue;
        const QString key = analysisKey(name);
        result[key] = QJsonValue();
        if (name != kAnalysisIso230_2 && !modelled) {
            skipped[key] = noModelledRun;
            continue;
        }
        try {
            result[key] = run();
        } catch (const CliError& e) {
            errors << QStringLiteral("%1: %2").arg(name, QString::fromStdString(e.what()));
        }
    }
    if (!skipped.isEmpty()) result[QStringLiteral("skipped")] = skipped;
    if (!errors.isEmpty()) result[QStringLiteral("error")] = errors.join(QStringLiteral("; "));
    printJson(result);
    return errors.isEmpty() ? kExitOk : kExitFailure;
}

}  // namespace driftlab::cli
