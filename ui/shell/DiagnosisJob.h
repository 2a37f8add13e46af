#pragma once
// The work behind the Diagnosis page, on a worker thread (BackgroundJob):
// diagnose the campaign (flagged samples left out, as `driftlab-cli
// diagnose`), store the diagnosis, and keep the held-out runs' data for the
// before/after plots. Adopting an extension is a separate, short store write.

#include <optional>

#include "core/diagnosis/Diagnosis.h"
#include "ui/shell/BackgroundJob.h"

namespace driftlab::ui {

struct DiagnosisOutcome {
    QString error;  ///< empty on success (and when cancelled)
    bool cancelled = false;
    QString note;
    diagnosis::DiagnosisResult result;
    std::vector<models::RunData> test_runs;  ///< the held-out runs, for the plots
    std::optional<qint64> diagnosis_id;      ///< the stored record
};

DiagnosisOutcome runDiagnosis(const QString& storePath, qint64 campaignId, JobControl& control);

}  // namespace driftlab::ui
