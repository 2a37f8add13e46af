#pragma once
// What a batch asks of each campaign (docs/batch.md): its name and runs and,
// per analysis asked for, the short result `batch` reports. An analysis that
// does not apply (no positioning run, no feed-axis run) is null and says why
// under "skipped"; one that fails is null with its reason under "error", the
// other analyses' results kept. Shared by `driftlab-cli batch-item` and the
// GUI; nothing is written.

#include <QJsonObject>
#include <QStringList>
#include <functional>

#include "core/domain/Campaign.h"

namespace driftlab::db {

/// The analyses a batch runs, as `--what` names them.
inline const QString kAnalysisInfo = QStringLiteral("info");
inline const QString kAnalysisIso230_2 = QStringLiteral("iso230-2");
inline const QString kAnalysisFit = QStringLiteral("fit");
inline const QString kAnalysisDiagnose = QStringLiteral("diagnose");
/// Every analysis, in the order they run.
QStringList batchAnalyses();
/// The JSON key of an analysis's result: "iso230_2", "fit", "diagnosis".
QString analysisKey(const QString& analysis);

struct BatchAnalysisOptions {
    QStringList analyses;  ///< of batchAnalyses(); unknown names are ignored
    /// Told which analysis runs ("fit") and the share of them done.
    std::function<void(const QString& what, double fraction)> progress;
    /// Asked before each analysis and inside the fit and the diagnosis; true stops.
    std::function<bool()> cancelled;
};

struct BatchAnalysis {
    /// name, runs, (info: machine, axis, channels), a key per analysis asked
    /// for, "skipped" and "error" when there are any.
    QJsonObject json;
    QStringList errors;      ///< "fit: why", per analysis that failed
    bool cancelled = false;  ///< stopped before every analysis ran: json is incomplete
    bool ok() const { return errors.isEmpty() && !cancelled; }
};

BatchAnalysis analyseCampaign(const Campaign& campaign, const BatchAnalysisOptions& options);

}  // namespace driftlab::db
