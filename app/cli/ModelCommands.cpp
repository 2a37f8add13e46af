// fit and compare: thermal-error models on a campaign (docs/models.md and docs/cli.md).
#include <QJsonArray>
#include <cmath>

#include "app/cli/CliCommon.h"
#include "app/cli/FlaggedSamples.h"
#include "core/models/ModelFactory.h"
#include "core/models/ModelScore.h"
#include "core/models/ModelledRuns.h"
#include "db/HeldOutFit.h"

namespace driftlab::cli {
namespace {

/// What the diagonal of the cross-state matrix is: not a held-out score.
const QString kDiagonal = QStringLiteral("training score (fitted and scored on the same run)");

const QCommandLineOption kTargetOption{
    QStringLiteral("target"),
    QStringLiteral(
        "A drift channel to model (spindle/ETVE runs) instead of the positioning error."),
    QStringLiteral("CH")};

}  // namespace

int fitCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption model{
        QStringLiteral("model"),
        QStringLiteral("Model: %1, or auto (combines the families by cross-validation over "
                       "the training runs and says with what weights).")
            .arg(models::modelNames().join(", ")),
        QStringLiteral("NAME")};
    const QCommandLineOption train{
        QStringLiteral("train"),
        QStringLiteral("Training runs (default: the first run that is not a test run)."),
        QStringLiteral("R,..")};
    const QCommandLineOption test{
        QStringLiteral("test"),
        QStringLiteral("Held-out test runs, none of them a training run (default: every other "
                       "run). With none, the score is a training score."),
        QStringLiteral("R,..")};
    parseArguments(parser, args,
                   campaignSourceOptions()
                       << model << train << test << kTargetOption << keepFlaggedOption(),
                   campaignSourceArguments({model}));
    const std::optional<QStringList> trainRuns =
        parser.isSet(train) ? std::optional(runList(parser.value(train))) : std::nullopt;
    const std::optional<QStringList> testRuns =
        parser.isSet(test) ? std::optional(runList(parser.value(test))) : std::nullopt;
    refuseOverlappingRuns(trainRuns.value_or(QStringList()), testRuns.value_or(QStringList()));
    db::makeModelOrFail(parser.value(model));  // refused before the campaign is read
    Campaign campaign = loadCampaignSource(parser, db::StoreAccess::ReadWrite);
    const std::optional<db::MaskedSamples> masked = leaveOutFlaggedSamples(parser, campaign);
    db::HeldOutFit r = db::fitHeldOut(
        campaign,
        {parser.value(model), trainRuns, testRuns, parser.value(kTargetOption), printProgress, {}});
    if (masked) r.record.metrics[QStringLiteral("flagged_left_out")] = masked->json();
    storeFitIfFromDatabase(parser, r.record);

    if (parser.isSet(QStringLiteral("json"))) {
        printJson(r.json());
        return 0;
    }
    const models::FitSummary& fit = r.fit;
    const models::Score& score = r.score;
    printLine(fit.message);
    for (const auto& [name, p] : fit.parameters)
        printLine(QStringLiteral("  %1 = %2 ± %3 %4")
                      .arg(name, -12)
                      .arg(p.value, 0, 'g', 5)
                      .arg(std::isfinite(p.sigma) ? QString::number(p.sigma, 'g', 2)
                                                  : QStringLiteral("?"))
                      .arg(p.unit));
    for (const QString& note : fit.notes) printLine(QStringLiteral("  note: ") + note);
    printLine((r.heldOut() ? QStringLiteral("held-out score on %1 (runs the fit has not seen)")
                           : QStringLiteral("training score on %1 (the runs it was fitted on; no "
                                            "run held out, so not a held-out score)"))
                  .arg(r.scoredRuns().join(QLatin1Char(','))) +
              QStringLiteral(": RMS %1 µm, peak %2 µm, %3 % of the thermal error removed")
                  .arg(score.rms_um, 0, 'f', 2)
                  .arg(score.peak_um, 0, 'f', 2)
                  .arg(100 * score.reduction, 0, 'f', 1));
    for (const QString& line : r.trustLines()) printLine(line);
    // Where the held-out score is an extrapolation, by what the runs left.
    const auto beyond = [](const QString& what, const QStringList& lines) {
        if (lines.isEmpty()) return;
        printLine(QStringLiteral("beyond the training runs' %1 (the prediction extrapolates "
                                 "there):")
                      .arg(what));
        for (const QString& line : lines) printLine(QStringLiteral("  ") + line);
    };
    beyond(QStringLiteral("temperature rises"),
           models::describeRisesBeyondTraining(r.beyondTraining));
    beyond(QStringLiteral("spindle speeds"), models::describeSpeedsBeyondTraining(r.speedsBeyond));
    return 0;
}

int compareCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption only{QStringLiteral("models"),
                                  QStringLiteral("Models to compare (default: all)."),
                                  QStringLiteral("NAME,..")};
    parseArguments(parser, args,
                   campaignSourceOptions() << only << kTargetOption << keepFlaggedOption(),
                   campaignSourceArguments());
    Campaign campaign = loadCampaignSource(parser);
    leaveOutFlaggedSamples(parser, campaign);
    const QString target = parser.value(kTargetOption);
    const QStringList runs = models::modelledRuns(campaign, target);
    const auto data = db::modelDataset(campaign, runs, target);
    const QStringList names =
        parser.isSet(only) ? runList(parser.value(only)) : models::modelNamesFor(target);

    QJsonObject modelsJson;
    for (int k = 0; k < names.size(); ++k) {
        if (!models::makeModel(names[k]))
            throw CliError(QStringLiteral("--models: '%1' is not a model").arg(names[k]), 2);
        const models::CrossStateMatrix matrix =
            models::crossStateMatrix(names[k], data, [&](double f) {
                return printProgress(QStringLiteral("comparing"), (k + f) / names.size());
            });
        QJsonArray rows;
        for (const auto& row : matrix.rms_um) {
            QJsonArray r;
            for (double v : row) r << jsonNumber(v);
            rows << r;
        }
        modelsJson[names[k]] =
            QJsonObject{{QStringLiteral("rms_um"), rows},
                        {QStringLiteral("errors"), QJsonArray::fromStringList(matrix.errors)}};
    }
    printProgress(QStringLiteral("comparing"), 1);
    if (parser.isSet(QStringLiteral("json"))) {
        printJson({{QStringLiteral("runs"), QJsonArray::fromStringList(runs)},
                   {QStringLiteral("models"), modelsJson},
                   {QStringLiteral("diagonal"), kDiagonal}});
        return 0;
    }
    printLine(
        QStringLiteral("RMS residual (µm) on each run (columns) of the model fitted on "
                       "each run (rows)"));
    printLine(QStringLiteral("(…) on the diagonal: %1; off it: held-out scores").arg(kDiagonal));
    for (const QString& name : names) {
        printLine(QStringLiteral("\n%1").arg(name));
        QString header = QStringLiteral("%1").arg(QString(), -8);
        for (const QString& r : runs) header += QStringLiteral("%1").arg(r, 9);
        printLine(header);
        const QJsonArray rows = modelsJson[name].toObject()[QStringLiteral("rms_um")].toArray();
        for (int i = 0; i < rows.size(); ++i) {
            QString line = QStringLiteral("%1").arg(runs[i], -8);
            const QJsonArray row = rows[i].toArray();
            for (int j = 0; j < row.size(); ++j) {
                const QString v = row[j].isNull() ? QStringLiteral("—")
                                                  : QString::number(row[j].toDouble(), 'f', 2);
                line += QStringLiteral("%1").arg(i == j ? QStringLiteral("(%1)").arg(v) : v, 9);
            }
            printLine(line);
        }
        for (const auto& e : modelsJson[name].toObject()[QStringLiteral("errors")].toArray())
            printLine(QStringLiteral("  ") + e.toString());
    }
    return 0;
}

}  // namespace driftlab::cli
