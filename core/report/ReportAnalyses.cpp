#include "core/report/ReportAnalyses.h"

#include <algorithm>
#include <cmath>

#include "core/models/ModelFactory.h"
#include "core/models/ModelledRuns.h"

namespace driftlab::report {

ModelSection compareModels(const Campaign& campaign, const std::function<bool(double)>& progress) {
    ModelSection s;
    s.diagonal = QStringLiteral("training score (fitted and scored on the same run)");
    s.runs = models::modelledRuns(campaign);
    if (s.runs.size() < 2) {
        s.not_applicable = QStringLiteral(
                               "no model comparison: it needs two feed-axis runs with positioning "
                               "readings, the campaign has %1")
                               .arg(s.runs.size());
        return s;
    }
    const models::DatasetResult data = models::buildDataset(campaign, s.runs);
    if (!data.ok()) {
        s.not_applicable = QStringLiteral("no model comparison: ") + data.error;
        return s;
    }
    s.gaps = models::gapsOf(data.runs);
    const QStringList names = models::modelNames();
    for (int k = 0; k < names.size(); ++k) {
        models::CrossStateMatrix matrix = models::crossStateMatrix(
            names[k], data.runs, [&](double f) { return progress((k + f) / names.size()); });
        if (matrix.cancelled) return s;
        s.models.push_back({names[k], std::move(matrix)});
    }
    return s;
}

DiagnosisSection diagnoseCampaign(const Campaign& campaign,
                                  const std::function<bool(double)>& progress) {
    DiagnosisSection s;
    diagnosis::DiagnosisOptions options;
    options.progress = progress;
    s.result = diagnosis::diagnose(campaign, options);
    if (!s.result.ok()) {
        s.not_applicable = QStringLiteral("no diagnosis: ") + s.result.error;
        return s;
    }
    const models::DatasetResult test = models::buildDataset(campaign, s.result.test_runs);
    if (test.ok()) s.test_runs = test.runs;
    return s;
}

CompensationSection compensate(const PositioningSection& positioning) {
    CompensationSection s;
    if (!positioning.not_applicable.isEmpty()) {
        s.not_applicable = QStringLiteral("no compensation table: ") + positioning.not_applicable;
        return s;
    }
    s.run_id = positioning.run_id;
    const compensation::TableResult built =
        compensation::buildTable(positioning.evaluation, compensation::TableSettings{});
    if (!built.ok()) {
        s.not_applicable = QStringLiteral("no compensation table: ") + built.error;
        return s;
    }
    s.table = built.table;
    s.warnings = built.warnings;
    const auto peak = [](double current, double v) {
        return std::isfinite(v) ? std::max(current, std::abs(v)) : current;
    };
    for (const iso::TargetResult& t : positioning.evaluation.targets) {
        CompensatedTarget c;
        c.target_mm = t.target_mm;
        c.before_up_um = t.mean_up_um;
        c.before_down_um = t.mean_down_um;
        c.after_up_um = t.mean_up_um + correctionAt(s.table, t.target_mm, Direction::Positive);
        c.after_down_um = t.mean_down_um + correctionAt(s.table, t.target_mm, Direction::Negative);
        s.before_peak_um = peak(peak(s.before_peak_um, c.before_up_um), c.before_down_um);
        s.residual_peak_um = peak(peak(s.residual_peak_um, c.after_up_um), c.after_down_um);
        s.targets.push_back(c);
    }
    return s;
}

}  // namespace driftlab::report
