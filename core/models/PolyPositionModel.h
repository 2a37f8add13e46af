#pragma once
// Polynomial-in-temperature × position model:
//   positioning error: E(x,t) = (Σ_{i=1..d} a_i·ΔT_nut^i + b·ΔT_bearing + c)·(x − x_fixed)
//   drift channel:     E(t)   =  Σ_{i=1..d} a_i·ΔT_nut^i + b·ΔT_bearing + c
// The degree d ≤ 4 is chosen by cross-validation on the training runs.

#include <QString>

#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

struct PolyPositionOptions {
    int max_degree = 4;
    /// Cross-validation blocks in time when there is a single training run.
    int time_blocks = 5;
};

class PolyPositionModel final : public ThermalErrorModel {
public:
    explicit PolyPositionModel(PolyPositionOptions options = {});
    QString name() const override { return QStringLiteral("poly-position"); }
    QString describe() const override;

protected:
    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;

private:
    Eigen::MatrixXd design(const RunData& run, const std::vector<PredictionPoint>& at,
                           int degree) const;

    PolyPositionOptions m_options;
    QString m_nut, m_bearing;
    int m_degree = 0;
    Eigen::VectorXd m_coefficients;  ///< a_1..a_d, b, c
};

}  // namespace driftlab::models
