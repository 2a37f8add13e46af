#pragma once
// A thermal-error model built on LaggedRegression: a concrete model only says
// which heat-source inputs drive its lag terms (exponential: screw or spindle
// speed).

#include <QStringList>
#include <vector>

#include "core/models/LaggedRegression.h"
#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

class LagModel : public ThermalErrorModel {
protected:
    LagModel(std::vector<LagTerm> terms, LagSearchOptions options);

    /// The run's heat-source inputs, indexed as the terms' `input`. Throws
    /// ModelError when the run cannot give them.
    virtual std::vector<PiecewiseInput> inputs(const RunData& run) const = 0;
    /// The columns or channels the inputs come from, for the summary.
    virtual QStringList inputSignals(const RunData& run) const = 0;

    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;

private:
    LagCase lagCase(const RunData& run, const std::vector<PredictionPoint>& at) const;

    LaggedRegression m_regression;
};

}  // namespace driftlab::models
