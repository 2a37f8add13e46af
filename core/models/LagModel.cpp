#include "core/models/LagModel.h"

#include <algorithm>

#include "core/models/RunDataAccess.h"

namespace driftlab::models {

LagModel::LagModel(std::vector<LagTerm> terms, LagSearchOptions options)
    : m_regression(std::move(terms), options) {}

LagCase LagModel::lagCase(const RunData& run, const std::vector<PredictionPoint>& at) const {
    LagCase c;
    for (const PredictionPoint& p : at) c.time_s.push_back(p.time_s);
    c.dx = positionsFromFixedEnd(run, at);
    c.inputs = inputs(run);
    return c;
}

FitSummary LagModel::fitRuns(const std::vector<RunData>& training) {
    std::vector<LagCase> cases;
    std::vector<Eigen::VectorXd> observed;
    for (const RunData& run : training) {
        cases.push_back(lagCase(run, run.observationPoints()));
        observed.push_back(run.observedErrors());
    }
    FitSummary summary = m_regression.fit(cases, observed, training.front().positionDependent());
    summary.inputs = inputSignals(training.front());
    return summary;
}

Eigen::VectorXd LagModel::predictRun(const RunData& run,
                                     const std::vector<PredictionPoint>& at) const {
    return m_regression.predict(lagCase(run, at));
}

}  // namespace driftlab::models
