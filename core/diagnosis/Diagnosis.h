#pragma once
// What the simulation gets wrong, its cause, the extended model and its gain
// (DESIGN.md section 6): fit the base heat-transfer model on training runs,
// refit every candidate effect, score all on held-out runs, and name the cause
// only when the held-out gain is real and the extra parameter is significant.

#include <QStringList>
#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "core/diagnosis/ResidualStructure.h"
#include "core/domain/Campaign.h"
#include "core/models/HeatTransferModel.h"

namespace driftlab::diagnosis {

struct DiagnosisOptions {
    QStringList train_runs, test_runs;  ///< both empty: split automatically
    /// An extension is significant when it lowers BIC on the training runs by
    /// more than this (≈ "very strong" evidence in Kass & Raftery's scale) …
    double min_bic_drop = 10;
    /// … and removes at least this share of the held-out residual.
    double min_test_gain = 0.05;
    /// A cause is named only when its extension leaves the held-out residual
    /// within this many times the reading noise (see leavesOnlyNoise); more
    /// left over means the candidate explains part of something else
    /// (verdict `unexplained`).
    double max_residual_over_noise = 2;
    std::function<bool(double fraction)> progress;  ///< false cancels
};

struct Finding {
    QString cause;
    QString parameter_name;
    models::Parameter parameter;
    double confidence = 0;
    bool significant = false;
    double bic_drop = 0;
    QString evidence;
    /// 1 − √(χ²_after/χ²_before) on the held-out runs, temperatures and
    /// positioning errors together (a sensor effect shows in temperatures).
    double reduction = 0;
    /// What the extension leaves on the held-out runs (the base model's is
    /// DiagnosisResult::base_test).
    ResidualSummary test_after;
    models::FitSummary fit;
    std::shared_ptr<const models::HeatTransferModel> model;  ///< the fitted extension
};

struct DiagnosisResult {
    QString error;  ///< empty on success
    bool ok() const { return error.isEmpty(); }
    QStringList train_runs, test_runs;
    models::FitSummary base_fit;
    ResidualSummary base_test;
    std::vector<Finding> findings;  ///< sorted by held-out reduction, best first
    QString verdict;                ///< a cause id, "none" or "unexplained"
    QString verdict_evidence;       ///< for none/unexplained: what the residual is
    /// The base residuals on the test runs (for the residual map).
    std::vector<models::ReadingResiduals> base_residuals;
    /// The adopted extension's residuals on the test runs (empty without a cause).
    std::vector<models::ReadingResiduals> adopted_residuals;
};

/// Runs split automatically: the last 40 % (at least one) of the feed-axis
/// runs are the test runs, the rest train; no run is in both.
void splitRuns(const Campaign& campaign, QStringList* train, QStringList* test);

DiagnosisResult diagnose(const Campaign& campaign, const DiagnosisOptions& options = {});

}  // namespace driftlab::diagnosis
