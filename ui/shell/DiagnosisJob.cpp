#include "ui/shell/DiagnosisJob.h"

#include "db/DiagnosisRecords.h"
#include "ui/shell/FitJob.h"

namespace driftlab::ui {

DiagnosisOutcome runDiagnosis(const QString& storePath, qint64 campaignId, JobControl& control) {
    DiagnosisOutcome out;
    control.progress(0);
    auto campaign = loadCampaignForModels(storePath, campaignId, &out.note, &out.error);
    if (!campaign) return out;
    diagnosis::DiagnosisOptions options;
    options.progress = [&control](double f) { return control.progress(f); };
    out.result = diagnosis::diagnose(*campaign, options);
    if (control.cancelled()) {
        out.cancelled = true;
        return out;
    }
    if (!out.result.ok()) {
        out.error = out.result.error;
        return out;
    }
    const models::DatasetResult test = models::buildDataset(*campaign, out.result.test_runs);
    if (!test.ok()) {
        out.error = test.error;
        return out;
    }
    out.test_runs = test.runs;
    auto store = db::CampaignStore::open(storePath, db::StoreAccess::ReadWrite, &out.error);
    if (!store) return out;
    out.diagnosis_id = db::storeDiagnosis(*store, campaignId,
                                          {0, db::kDiagnosisBaseModel, out.result.verdict,
                                           std::nullopt, db::diagnosisJson(out.result)},
                                          &out.error);
    return out;
}

}  // namespace driftlab::ui
