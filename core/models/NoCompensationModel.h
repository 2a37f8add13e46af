#pragma once
// `none`: no compensation, a thermal error of zero everywhere. The candidate
// every model must beat: a model that does worse than it on its own
// cross-validation would make the machine worse (no harm).

#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

class NoCompensationModel final : public ThermalErrorModel {
public:
    QString name() const override { return QStringLiteral("none"); }
    QString describe() const override {
        return QStringLiteral(
            "No compensation: predicts no thermal error, the candidate every model must beat.");
    }

protected:
    FitSummary fitRuns(const std::vector<RunData>&) override {
        FitSummary summary;
        summary.notes << QStringLiteral("no compensation: the thermal error is left as it is");
        return summary;
    }
    Eigen::VectorXd predictRun(const RunData&,
                               const std::vector<PredictionPoint>& at) const override {
        return Eigen::VectorXd::Zero(Eigen::Index(at.size()));
    }
};

}  // namespace driftlab::models
