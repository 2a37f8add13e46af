#pragma once
// `ridge-heat`: every temperature rise of a spindle's drift channel and the
// spindle's heat through a first-order lag, with one common offset, fitted
// with a penalty on the rises' gains (ridge regression; Hoerl & Kennard 1970):
//   E(t) = Σ_k a_k·ΔT_k(t) + q·L_τ[n^p](t) + c,
//   minimising ‖y − X·b‖² + λ·N·Σ_k (s_k·a_k)²
// over N rows, each column scaled to unit RMS (s_k the rise's RMS), so λ
// weighs every thermometer alike whatever its range. Sixteen thermometers
// around the heat paths are nearly collinear: least squares on all of them
// trades large gains of opposite sign that follow the training runs' noise
// and miss a run heated differently; the penalty shrinks that trade, and
// leaves the heat's gain and the offset free. λ ∈ {0} ∪ 10^[−4, 1] (11 steps)
// and the heat (none, or p = 1 or 2 and τ from `arx-all`'s heat grid) are
// chosen together by cross-validation over the training runs; λ = 0 is least
// squares, so no 2 % bar is needed between them.

#include <QStringList>
#include <vector>

#include "core/models/RisesHeatSearch.h"
#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

/// The penalised least squares of `ridge-heat` from the normal equations
/// XᵀX (`gram`) and Xᵀy (`moment`) of `rows` rows: each column scaled to unit
/// RMS, λ·rows added to the first `penalised` columns' diagonal. Empty when
/// the system is singular (λ = 0 on collinear columns).
Eigen::VectorXd ridgeSolve(const Eigen::MatrixXd& gram, const Eigen::VectorXd& moment, double rows,
                           double lambda, Eigen::Index penalised);

class RidgeHeatModel final : public ThermalErrorModel {
public:
    explicit RidgeHeatModel(RisesHeatOptions options = {});
    QString name() const override { return QStringLiteral("ridge-heat"); }
    QString describe() const override;
    /// The penalties tried: 0, then 10⁻⁴ … 10 evenly on a log scale.
    static std::vector<double> penalties();

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
    double m_lambda = 0;
    Eigen::VectorXd m_coefficients;
};

}  // namespace driftlab::models
