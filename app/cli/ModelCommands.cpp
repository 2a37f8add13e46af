// fit and compare: thermal-error models on a campaign (DESIGN.md sections 5, 9).
#include <QJsonArray>
#include <cmath>

#include "app/cli/CliCommon.h"
#include "app/cli/FlaggedSamples.h"
#include "core/models/ModelFactory.h"
#include "core/models/ModelScore.h"
#include "core/models/ModelledRuns.h"
#include "db/ModelFitRecords.h"

namespace driftlab::cli {
namespace {

std::vector<models::RunData> dataset(const Campaign& campaign, const QStringList& runs,
                                     const QString& target) {
    models::DatasetOptions options;
    options.target_channel = target;
    models::DatasetResult result = models::buildDataset(campaign, runs, options);
    if (!result.ok()) throw CliError(result.error);
    return std::move(result.runs);
}

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
        QStringLiteral("model"), QStringLiteral("Model: %1.").arg(models::modelNames().join(", ")),
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
    auto m = models::makeModel(parser.value(model));
    if (!m)
        throw CliError(QStringLiteral("--model: '%1' is not a model (%2)")
                           .arg(parser.value(model), models::modelNames().join(", ")),
                       2);
    QStringList trainRuns = runList(parser.value(train));
    QStringList testRuns = runList(parser.value(test));
    refuseOverlappingRuns(trainRuns, testRuns);
    Campaign campaign = loadCampaignSource(parser, db::StoreAccess::ReadWrite);
    leaveOutFlaggedSamples(parser, campaign);
    const QString target = parser.value(kTargetOption);
    const QStringList all = models::modelledRuns(campaign, target);
    if (!parser.isSet(train))
        for (const QString& id : all)
            if (!testRuns.contains(id)) {
                trainRuns << id;
                break;
            }
    if (!parser.isSet(test))
        for (const QString& id : all)
            if (!trainRuns.contains(id)) testRuns << id;
    if (trainRuns.isEmpty()) throw CliError(QStringLiteral("no run to fit on"));

    printProgress(QStringLiteral("fitting ") + m->name(), 0);
    const models::FitSummary fit = m->fit(dataset(campaign, trainRuns, target));
    printProgress(QStringLiteral("fitting ") + m->name(), 1);
    if (!fit.success) throw CliError(fit.message);

    // With no run left out (one run, or --test with none) the only score there
    // is comes from the training runs: it is labelled so, and never stands
    // where a script or the database expects a held-out score.
    const bool heldOut = !testRuns.isEmpty();
    const QStringList scoredRuns = heldOut ? testRuns : trainRuns;
    const models::Score score = models::scoreModel(*m, dataset(campaign, scoredRuns, target));
    if (!score.ok()) throw CliError(score.error);
    const db::ModelFitRecord record =
        db::modelFitRecord(m->name(), target, trainRuns, testRuns, fit, score);
    const QJsonObject& parameters = record.parameters;
    const QJsonObject& metrics = record.metrics;
    const QJsonObject figures = db::scoreJson(score);
    const QString scoreKind = metrics[QStringLiteral("score_kind")].toString();
    storeFitIfFromDatabase(parser, record);

    if (parser.isSet(QStringLiteral("json"))) {
        QJsonObject scored = figures;
        scored[QStringLiteral("runs")] = QJsonArray::fromStringList(scoredRuns);
        printJson({{QStringLiteral("model"), m->name()},
                   {QStringLiteral("train_runs"), QJsonArray::fromStringList(trainRuns)},
                   {QStringLiteral("test_runs"), QJsonArray::fromStringList(testRuns)},
                   {QStringLiteral("parameters"), parameters},
                   {QStringLiteral("score_kind"), scoreKind},
                   {QStringLiteral("score"), scored},
                   {QStringLiteral("test"), heldOut ? figures : QJsonObject()},
                   {QStringLiteral("fit"),
                    QJsonObject{{QStringLiteral("message"), fit.message},
                                {QStringLiteral("rms_um"), jsonNumber(fit.rms_um)},
                                {QStringLiteral("notes"), QJsonArray::fromStringList(fit.notes)},
                                {QStringLiteral("metrics"), metrics}}}});
        return 0;
    }
    printLine(fit.message);
    for (const auto& [name, p] : fit.parameters)
        printLine(QStringLiteral("  %1 = %2 ± %3 %4")
                      .arg(name, -12)
                      .arg(p.value, 0, 'g', 5)
                      .arg(std::isfinite(p.sigma) ? QString::number(p.sigma, 'g', 2)
                                                  : QStringLiteral("?"))
                      .arg(p.unit));
    for (const QString& note : fit.notes) printLine(QStringLiteral("  note: ") + note);
    printLine((heldOut ? QStringLiteral("held-out score on %1 (runs the fit has not seen)")
                       : QStringLiteral("training score on %1 (the runs it was fitted on; no "
                                        "run held out, so not a held-out score)"))
                  .arg(scoredRuns.join(QLatin1Char(','))) +
              QStringLiteral(": RMS %1 µm, peak %2 µm, %3 % of the thermal error removed")
                  .arg(score.rms_um, 0, 'f', 2)
                  .arg(score.peak_um, 0, 'f', 2)
                  .arg(100 * score.reduction, 0, 'f', 1));
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
    const auto data = dataset(campaign, runs, target);
    QStringList names = parser.isSet(only) ? runList(parser.value(only)) : models::modelNames();
    // The heat-transfer model predicts the screw; it has nothing to say on a drift channel.
    if (!target.isEmpty() && !parser.isSet(only)) names.removeAll(QStringLiteral("heat-transfer"));

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
