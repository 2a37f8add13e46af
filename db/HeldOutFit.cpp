#include "db/HeldOutFit.h"

#include <QJsonArray>

#include "core/models/ModelFactory.h"
#include "core/models/ModelledRuns.h"
#include "db/ModelFitRecords.h"
#include "db/ModelTrustJson.h"

namespace driftlab::db {
std::vector<models::RunData> modelDataset(const Campaign& campaign, const QStringList& runs,
                                          const QString& target) {
    models::DatasetOptions options;
    options.target_channel = target;
    models::DatasetResult result = models::buildDataset(campaign, runs, options);
    if (!result.ok()) throw ServiceError(result.error);
    return std::move(result.runs);
}

std::unique_ptr<models::ThermalErrorModel> makeModelOrFail(const QString& name) {
    auto model = models::makeModel(name);
    if (!model)
        throw ServiceError(QStringLiteral("--model: '%1' is not a model (%2)")
                               .arg(name, models::fitModelNames().join(", ")),
                           ServiceError::Kind::BadRequest);
    return model;
}

QJsonObject HeldOutFit::json() const {
    const QJsonObject& metrics = record.metrics;
    QJsonObject scored = scoreJson(score);
    scored[QStringLiteral("runs")] = QJsonArray::fromStringList(scoredRuns());
    QJsonArray beyond;
    for (const models::RiseBeyondTraining& b : beyondTraining)
        beyond.append(QJsonObject{{QStringLiteral("run"), b.run},
                                  {QStringLiteral("channel"), b.channel},
                                  {QStringLiteral("role"), toString(b.role)},
                                  {QStringLiteral("rise_K"), b.rise_K},
                                  {QStringLiteral("training_low_K"), b.training_low_K},
                                  {QStringLiteral("training_high_K"), b.training_high_K}});
    QJsonArray speeds;
    for (const models::SpeedBeyondTraining& b : speedsBeyond)
        speeds.append(QJsonObject{{QStringLiteral("run"), b.run},
                                  {QStringLiteral("channel"), b.channel},
                                  {QStringLiteral("speed_rpm"), b.speed_rpm},
                                  {QStringLiteral("training_low_rpm"), b.training_low_rpm},
                                  {QStringLiteral("training_high_rpm"), b.training_high_rpm}});
    QJsonObject tested = heldOut() ? scoreJson(score) : QJsonObject();
    if (heldOut()) {
        tested[QStringLiteral("coverage")] = coverageJson(coverage);
        tested[QStringLiteral("worse_than_none")] = heldOutWorseThanNone();
    }
    QJsonObject shownMetrics = metrics;
    shownMetrics.remove(QStringLiteral("validation"));  // at the top level
    return {{QStringLiteral("model"), model->name()},
            {QStringLiteral("train_runs"), QJsonArray::fromStringList(trainRuns)},
            {QStringLiteral("test_runs"), QJsonArray::fromStringList(testRuns)},
            {QStringLiteral("parameters"), record.parameters},
            {QStringLiteral("score_kind"), metrics[QStringLiteral("score_kind")].toString()},
            {QStringLiteral("score"), scored},
            {QStringLiteral("test"), tested},
            {QStringLiteral("validation"), validationJson(validation)},
            {QStringLiteral("gaps"), gapsJson(gaps)},
            {QStringLiteral("beyond_training"), beyond},
            {QStringLiteral("beyond_training_speed"), speeds},
            {QStringLiteral("fit"),
             QJsonObject{{QStringLiteral("message"), fit.message},
                         {QStringLiteral("rms_um"), jsonNumber(fit.rms_um)},
                         {QStringLiteral("notes"), QJsonArray::fromStringList(fit.notes)},
                         {QStringLiteral("metrics"), shownMetrics}}}};
}

HeldOutFit fitHeldOut(const Campaign& campaign, const HeldOutFitOptions& options) {
    const QString& target = options.target;
    const auto checkCancelled = [&] {
        if (options.cancelled && options.cancelled())
            throw ServiceError(QStringLiteral("the fit was cancelled"));
    };
    HeldOutFit r;
    r.model = makeModelOrFail(options.model);  // an unknown name is refused before any work
    r.trainRuns = options.train.value_or(QStringList());
    r.testRuns = options.test.value_or(QStringList());
    const QStringList all = models::modelledRuns(campaign, target);
    if (!options.train)
        for (const QString& id : all)
            if (!r.testRuns.contains(id)) {
                r.trainRuns << id;
                break;
            }
    if (!options.test)
        for (const QString& id : all)
            if (!r.trainRuns.contains(id)) r.testRuns << id;
    if (r.trainRuns.isEmpty())
        throw ServiceError(QStringLiteral("no run to fit on: ") +
                           (all.isEmpty() ? models::whyNoModelledRun(campaign, target)
                                          : QStringLiteral("--test holds out every modelled run")));

    const QString label = QStringLiteral("fitting ") + r.model->name();
    if (options.progress) options.progress(label, 0);
    const std::vector<models::RunData> training = modelDataset(campaign, r.trainRuns, target);
    models::ValidatedFit validated =
        models::fitValidated(options.model, training, options.cancelled);
    checkCancelled();
    if (options.progress) options.progress(label, 1);
    if (!validated.fit.success) throw ServiceError(validated.fit.message);
    r.model = std::move(validated.model);
    r.fit = std::move(validated.fit);
    r.validation = validated.validation;

    // With no run left out (one run, or --test with none) the only score there
    // is comes from the training runs: it is labelled so, and never stands
    // where a script or the database expects a held-out score.
    const std::vector<models::RunData> scored = modelDataset(campaign, r.scoredRuns(), target);
    r.score = models::scoreModel(*r.model, scored);
    if (!r.score.ok()) throw ServiceError(r.score.error);
    if (r.heldOut()) {
        r.beyondTraining = models::risesBeyondTraining(training, scored);
        r.speedsBeyond = models::speedsBeyondTraining(training, scored);
        r.coverage = models::coverageOf(*r.model, r.validation.interval, scored, training);
    }
    r.gaps = models::gapsOf(training);
    if (r.heldOut()) {
        const std::vector<models::DataGap> scoredGaps = models::gapsOf(scored);
        r.gaps.insert(r.gaps.end(), scoredGaps.begin(), scoredGaps.end());
    }
    r.record = modelFitRecord(r.model->name(), target, r.trainRuns, r.testRuns, r.fit, r.score);
    r.record.metrics[QStringLiteral("validation")] = validationJson(r.validation);
    return r;
}

QStringList HeldOutFit::trustLines() const {
    QStringList lines;
    if (heldOutWorseThanNone())
        lines << QStringLiteral(
                     "error: the model makes the held-out runs' thermal error worse, not "
                     "better: RMS %1 µm with it, %2 µm without (%3 %): do not compensate with it")
                     .arg(score.rms_um, 0, 'f', 2)
                     .arg(score.uncompensated_rms_um, 0, 'f', 2)
                     .arg(100 * score.reduction, 0, 'f', 0);
    if (validation.interval.known() && coverage.known())
        lines << QStringLiteral(
                     "prediction interval ±%1 µm (95 %)%2: %3 % of the held-out readings "
                     "inside it%4")
                     .arg(validation.interval.half_width_um, 0, 'f', 2)
                     .arg(models::extrapolationWords(validation.interval, extrapolates()))
                     .arg(100 * coverage.share, 0, 'f', 0)
                     .arg(coverage.farBelowClaim()
                              ? QStringLiteral(", far less than it claims: the held-out runs "
                                               "differ from the training runs more than the "
                                               "training runs differ among themselves")
                              : QString());
    lines << models::gapLines(gaps);
    return lines;
}

}  // namespace driftlab::db
