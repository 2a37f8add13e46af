#pragma once
// `lsall-heat`: least squares on every temperature rise of a spindle's drift
// channel and the spindle's heat through a first-order lag, with one offset
// common to all runs,
//   E(t) = Σ_k a_k·ΔT_k(t) + q·L_τ[n^p](t) + c,
// n the spindle's speed in 1000 rpm, p = 1 or 2 and τ chosen by
// cross-validation over the training runs (or no heat, unless the heat lowers
// the cross-validated RMS by 2 %). It is `arx-all` without its lagged rise
// and with one offset for all runs instead of each run's zero: the plain
// least squares a test engineer fits first, with the heat of the parts no
// thermometer sees (docs/models.md §3).

#include <QStringList>
#include <vector>

#include "core/models/RisesHeatSearch.h"
#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

class AllRisesHeatModel final : public ThermalErrorModel {
public:
    explicit AllRisesHeatModel(RisesHeatOptions options = {});
    QString name() const override { return QStringLiteral("lsall-heat"); }
    QString describe() const override;

protected:
    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;

private:
    /// [every rise, the heat (when chosen), 1] at the points.
    Eigen::MatrixXd design(const RunData& run, const std::vector<PredictionPoint>& at) const;

    RisesHeatOptions m_options;
    QStringList m_channels;
    SpindleHeat m_heat;
    Eigen::VectorXd m_coefficients;
};

}  // namespace driftlab::models
