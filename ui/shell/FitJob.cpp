#include "ui/shell/FitJob.h"

#include "core/models/ModelFactory.h"
#include "core/models/ModelledRuns.h"
#include "db/FlaggedSampleMask.h"
#include "db/ModelFitRecords.h"

namespace driftlab::ui {

std::optional<Campaign> loadCampaignForModels(const QString& storePath, qint64 campaignId,
                                              QString* note, QString* error,
                                              std::optional<db::MaskedSamples>* leftOut) {
    auto store = db::CampaignStore::open(storePath, db::StoreAccess::ReadOnly, error);
    if (!store) return std::nullopt;
    std::optional<Campaign> campaign = store->loadCampaign(campaignId, error);
    if (!campaign) return std::nullopt;
    const auto masked = db::leaveOutFlaggedSamples(*store, campaignId, *campaign, error);
    if (!masked) return std::nullopt;
    if (masked->flagged) {
        *note = masked->describe();
        if (leftOut) *leftOut = masked;
    }
    return campaign;
}

ModelledRunLists listModelledRuns(const QString& storePath, qint64 campaignId) {
    ModelledRunLists lists;
    QString note;
    auto campaign = loadCampaignForModels(storePath, campaignId, &note, &lists.error);
    if (!campaign) return lists;
    lists.targets << QString() << models::driftTargets(*campaign);
    for (const QString& target : lists.targets)
        lists.runs[target] = models::modelledRuns(*campaign, target);
    return lists;
}

FitOutcome runFit(const FitRequest& request, JobControl& control) {
    FitOutcome out;
    control.progress(0.02);
    auto campaign = loadCampaignForModels(request.store_path, request.campaign_id, &out.note,
                                          &out.error, &out.masked);
    if (!campaign) return out;
    if (!models::makeModel(request.model)) {
        out.error = QObject::tr("'%1' is not a model (%2)")
                        .arg(request.model, models::fitModelNames().join(QStringLiteral(", ")));
        return out;
    }
    if (request.train_runs.isEmpty()) {
        out.error = QObject::tr("choose at least one training run");
        return out;
    }
    models::DatasetOptions options;
    options.target_channel = request.target_channel;
    const models::DatasetResult train =
        models::buildDataset(*campaign, request.train_runs, options);
    out.held_out = !request.test_runs.isEmpty();
    const models::DatasetResult test = models::buildDataset(
        *campaign, out.held_out ? request.test_runs : request.train_runs, options);
    if (!train.ok() || !test.ok()) {
        out.error = train.ok() ? test.error : train.error;
        return out;
    }
    // The fit gives no fraction: "busy" until it is done.
    control.progress(-1);
    models::ValidatedFit validated =
        models::fitValidated(request.model, train.runs, [&control] { return control.cancelled(); });
    out.fit = validated.fit;
    out.validation = validated.validation;
    const std::unique_ptr<models::ThermalErrorModel> model = std::move(validated.model);
    if (control.cancelled()) {
        out.cancelled = true;
        return out;
    }
    if (!out.fit.success) {
        out.error = out.fit.message;
        return out;
    }
    control.progress(0.9);
    out.pooled = models::scoreModel(*model, test.runs);
    if (!out.pooled.ok()) {
        out.error = out.pooled.error;
        return out;
    }
    for (const models::RunData& run : test.runs) {
        RunPrediction p{run.run_id, run.observations, {}, {}, models::scoreModel(*model, {run})};
        p.predicted_um = model->predict(run).error_um;
        const bool beyond = models::beyondTraining(train.runs, run);
        if (out.validation.interval.known())
            for (const models::ErrorObservation& o : run.observations)
                p.interval_um.push_back(out.validation.interval.halfWidthAt(o.position_mm, beyond));
        out.runs.push_back(std::move(p));
    }
    out.gaps = models::gapsOf(train.runs);
    if (out.held_out) {
        out.beyond_training = models::risesBeyondTraining(train.runs, test.runs);
        out.speeds_beyond = models::speedsBeyondTraining(train.runs, test.runs);
        out.coverage = models::coverageOf(*model, out.validation.interval, test.runs, train.runs);
        const std::vector<models::DataGap> tested = models::gapsOf(test.runs);
        out.gaps.insert(out.gaps.end(), tested.begin(), tested.end());
    }
    // The last moment Cancel counts: once stored, the fit is a result.
    if (control.cancelled()) {
        out.cancelled = true;
        return out;
    }
    auto store =
        db::CampaignStore::open(request.store_path, db::StoreAccess::ReadWrite, &out.error);
    if (!store) return out;
    db::ModelFitRecord record =
        db::modelFitRecord(model->name(), request.target_channel, request.train_runs,
                           request.test_runs, out.fit, out.pooled);
    if (out.masked) record.metrics[QStringLiteral("flagged_left_out")] = out.masked->json();
    out.fit_id = db::storeModelFit(*store, request.campaign_id, record, &out.error);
    control.progress(1);
    return out;
}

CompareOutcome runCompare(const QString& storePath, qint64 campaignId, const QString& target,
                          JobControl& control) {
    CompareOutcome out;
    control.progress(0);
    auto campaign = loadCampaignForModels(storePath, campaignId, &out.note, &out.error);
    if (!campaign) return out;
    out.runs = models::modelledRuns(*campaign, target);
    models::DatasetOptions options;
    options.target_channel = target;
    const models::DatasetResult data = models::buildDataset(*campaign, out.runs, options);
    if (!data.ok()) {
        out.error = data.error;
        return out;
    }
    const QStringList names = models::modelNamesFor(target);
    for (int k = 0; k < names.size(); ++k) {
        models::CrossStateMatrix matrix = models::crossStateMatrix(
            names[k], data.runs,
            [&](double f) { return control.progress((k + f) / double(names.size())); });
        if (matrix.cancelled || control.cancelled()) {
            out.cancelled = true;
            out.matrices.clear();
            return out;
        }
        out.matrices.emplace_back(names[k], std::move(matrix));
    }
    return out;
}

}  // namespace driftlab::ui
