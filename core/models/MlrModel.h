#pragma once
// Multiple linear regression of the thermal error on temperature rises, with
// the sensors chosen by cross-validation (the "one or two well-placed sensors"
// model of industrial compensation):
//   positioning error: E(x,t) = Σ_j ΔT_j(t)·(a_j + b_j·(x − x_fixed))
//   drift channel:     E(t)   = Σ_j a_j·ΔT_j(t) + c

#include <QStringList>
#include <vector>

#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

struct MlrOptions {
    int max_sensors = 3;
    /// Inputs are rises relative to the ambient channel's rise (ΔT_j − ΔT_ambient).
    bool ambient_reference = false;
    /// Cross-validation blocks in time when there is a single training run.
    int time_blocks = 5;
};

/// A sensor subset and its cross-validated RMS on the training runs.
struct SubsetScore {
    QStringList sensors;
    double cv_rms_um = 0;
};

class MlrModel final : public ThermalErrorModel {
public:
    explicit MlrModel(MlrOptions options = {});
    QString name() const override { return QStringLiteral("mlr"); }
    QString describe() const override;
    /// From the last fit: the best subset of each size, one sensor first.
    const std::vector<SubsetScore>& bestSubsets() const { return m_best_subsets; }

protected:
    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;

private:
    /// The model inputs (rises, ambient-referenced if asked) of channels at points.
    Eigen::MatrixXd inputsAt(const RunData& run, const QStringList& channels,
                             const std::vector<PredictionPoint>& at) const;
    /// Design of the regression from the inputs of the chosen sensors.
    static Eigen::MatrixXd design(const Eigen::MatrixXd& inputs, const Eigen::VectorXd& dx,
                                  bool positionDependent);

    MlrOptions m_options;
    QString m_ambient;  ///< the reference channel when ambient_reference
    QStringList m_sensors;
    Eigen::VectorXd m_coefficients;
    std::vector<SubsetScore> m_best_subsets;
};

}  // namespace driftlab::models
