#pragma once
// `pcr-heat`: principal-component regression on the temperature rises of a
// spindle's drift channel, with the spindle's heat through a first-order lag
// and one common offset (Jolliffe, "Principal Component Analysis", §8.1):
//   z = (ΔT − μ)/σ over the training runs' rows, V the loadings of z's SVD,
//   E(t) = Σ_{i≤k} β_i·(z·V)_i(t) + q·L_τ[n^p](t) + c.
// Sixteen thermometers around the heat paths move together in a few
// patterns (the bearings warming, the housing, the slow column); least squares
// on all of them fits the small differences between neighbours too, which
// carry the training runs' noise. The first k components keep the patterns
// and drop those differences. k ∈ 1…16 and the heat (none, or p = 1 or 2 and
// τ from `arx-all`'s heat grid) are chosen together by cross-validation over
// the training runs, on loadings from all of the fit's runs.

#include <QStringList>
#include <vector>

#include "core/models/RisesHeatSearch.h"
#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

class PrincipalRisesHeatModel final : public ThermalErrorModel {
public:
    explicit PrincipalRisesHeatModel(RisesHeatOptions options = {});
    QString name() const override { return QStringLiteral("pcr-heat"); }
    QString describe() const override;
    /// The most components tried.
    static constexpr int kMaxComponents = 16;

protected:
    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;

private:
    /// [every rise, the heat (when chosen), 1] at the points: the components'
    /// gains carried back to each rise.
    Eigen::MatrixXd design(const RunData& run, const std::vector<PredictionPoint>& at) const;

    RisesHeatOptions m_options;
    QStringList m_channels;
    SpindleHeat m_heat;
    int m_components = 0;
    Eigen::VectorXd m_coefficients;  ///< per rise, the heat's, the offset
};

}  // namespace driftlab::models
