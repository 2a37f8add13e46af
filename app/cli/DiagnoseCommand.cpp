// diagnose: what the simulation gets wrong, the cause, the extension and its
// gain (docs/diagnosis.md), as the JSON scripts rely on.
#include <QDir>
#include <QJsonArray>

#include "app/cli/CliCommon.h"
#include "app/cli/FlaggedSamples.h"
#include "core/diagnosis/Diagnosis.h"
#include "db/DiagnosisRecords.h"
#include "ui/plots/DiagnosisPlots.h"

namespace driftlab::cli {
namespace {

QJsonArray writePlots(const Campaign& campaign, const diagnosis::DiagnosisResult& r,
                      const QString& directory) {
    QDir().mkpath(directory);
    const QDir dir(directory);
    QJsonArray written;
    const QStringList runs = r.test_runs;
    const models::DatasetResult data = models::buildDataset(campaign, runs);
    if (!data.ok()) throw CliError(data.error);
    QString error;
    for (std::size_t k = 0; k < r.base_residuals.size(); ++k) {
        const QString run = r.base_residuals[k].run_id;
        const QString map = dir.filePath(run + QStringLiteral("-residual-map.png"));
        if (!ui::saveResidualMap(
                r.base_residuals[k], map,
                QStringLiteral("%1: positioning residual of the base model").arg(run), &error))
            throw CliError(error);
        const QString curves = dir.filePath(run + QStringLiteral("-before-after.png"));
        const auto* adopted = diagnosis::adoptedResiduals(r, k);
        if (!ui::saveBeforeAfter(data.runs[k], r.base_residuals[k], adopted,
                                 QStringLiteral("with ") + r.verdict, curves,
                                 QStringLiteral("%1: verdict %2").arg(run, r.verdict), &error))
            throw CliError(error);
        written << map << curves;
    }
    return written;
}

}  // namespace

int diagnoseCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption train{
        QStringLiteral("train"),
        QStringLiteral("Training runs, given with --test (default: the first three fifths of "
                       "the feed-axis runs)."),
        QStringLiteral("R,..")};
    const QCommandLineOption test{
        QStringLiteral("test"),
        QStringLiteral("Held-out runs, none of them a training run, given with --train "
                       "(default: the other runs)."),
        QStringLiteral("R,..")};
    const QCommandLineOption plots{QStringLiteral("plots"),
                                   QStringLiteral("Write the residual map and before/after "
                                                  "curves of each held-out run into DIR."),
                                   QStringLiteral("DIR")};
    parseArguments(parser, args,
                   campaignSourceOptions() << train << test << plots << keepFlaggedOption(),
                   campaignSourceArguments());
    if (parser.isSet(train) != parser.isSet(test))
        throw CliError(QStringLiteral("give both --train and --test, or neither"), 2);
    diagnosis::DiagnosisOptions options;
    options.train_runs = runList(parser.value(train));
    options.test_runs = runList(parser.value(test));
    // Refused before the campaign is read: it is the command line that is wrong.
    refuseOverlappingRuns(options.train_runs, options.test_runs);
    Campaign campaign = loadCampaignSource(parser, db::StoreAccess::ReadWrite);
    leaveOutFlaggedSamples(parser, campaign);
    options.progress = [](double f) { return printProgress(QStringLiteral("diagnosing"), f); };
    const diagnosis::DiagnosisResult r = diagnosis::diagnose(campaign, options);
    if (!r.ok()) throw CliError(r.error);

    QJsonObject json = db::diagnosisJson(r);
    if (parser.isSet(plots))
        json[QStringLiteral("plots")] = writePlots(campaign, r, parser.value(plots));

    if (parser.isSet(QStringLiteral("db"))) {
        // The adopted extension is kept as a model fit, the diagnosis with it.
        std::optional<qint64> adopted;
        if (const diagnosis::Finding* f = diagnosis::verdictFinding(r))
            adopted = storeFitIfFromDatabase(parser, db::adoptedExtensionFit(r, *f));
        auto store = openSourceStore(parser, db::StoreAccess::ReadWrite);
        QString error;
        if (!db::storeDiagnosis(*store, parser.value(QStringLiteral("campaign")).toLongLong(),
                                {0, db::kDiagnosisBaseModel, r.verdict, adopted, json}, &error))
            throw CliError(error);
    }

    if (parser.isSet(QStringLiteral("json"))) {
        printJson(json);
        return 0;
    }
    printLine(QStringLiteral("trained on %1, held out %2")
                  .arg(r.train_runs.join(QLatin1Char(',')), r.test_runs.join(QLatin1Char(','))));
    for (const QString& note : r.base_fit.notes) printLine(QStringLiteral("base model: ") + note);
    printLine(
        QStringLiteral("base model on held-out runs: %1 µm RMS, peak %2 µm (reading noise %3 µm)")
            .arg(r.base_test.error_rms_um, 0, 'f', 2)
            .arg(r.base_test.error_peak_um, 0, 'f', 2)
            .arg(r.base_test.error_noise_um, 0, 'f', 2));
    for (const auto& f : r.findings)
        printLine(QStringLiteral("  %1 step %2 %3  gain %4 % on %5  ΔBIC %6  %7")
                      .arg(f.significant ? QStringLiteral("*") : QStringLiteral(" "))
                      .arg(f.step)
                      .arg(f.cause, -28)
                      .arg(100 * f.gain.reduction, 5, 'f', 1)
                      .arg(f.gain.quantity)
                      .arg(f.bic_drop, 8, 'f', 0)
                      .arg(diagnosis::parametersText(f)));
    printLine(
        QStringLiteral("verdict: %1").arg(r.verdict) +
        (r.causes.size() > 1
             ? QStringLiteral(" (causes in order: %1)").arg(r.causes.join(QStringLiteral(", ")))
             : QString()));
    if (!r.verdict_evidence.isEmpty()) printLine(r.verdict_evidence);
    for (const QString& cause : r.causes)
        if (const auto* f = diagnosis::adoptedFinding(r, cause))
            printLine(QStringLiteral("%1: %2").arg(cause, f->evidence));
    if (!r.remaining.isEmpty()) printLine(r.remaining);
    for (const QString& line : models::gapLines(r.gaps)) printLine(line);
    return 0;
}

}  // namespace driftlab::cli
