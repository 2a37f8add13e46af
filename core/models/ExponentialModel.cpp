#include "core/models/ExponentialModel.h"

#include "core/models/HeatSourceInputs.h"

namespace driftlab::models {
namespace {

std::vector<LagTerm> sourceTerms(int sources) {
    std::vector<LagTerm> terms;
    for (int k = 1; k <= sources; ++k)
        terms.push_back({QStringLiteral("source%1").arg(k), 0, QStringLiteral("rad/s")});
    return terms;
}

}  // namespace

ExponentialModel::ExponentialModel(ExponentialOptions options)
    : LagModel(sourceTerms(options.sources), options.search), m_sources(options.sources) {}

QString ExponentialModel::describe() const {
    return QStringLiteral(
               "%1 heat source(s) driven by the screw (or spindle) speed, each rising "
               "and decaying exponentially with its own time constant, with a gain "
               "linear in position.")
        .arg(m_sources);
}

std::vector<PiecewiseInput> ExponentialModel::inputs(const RunData& run) const {
    return {run.positionDependent() ? screwSpeed(run, name()) : spindleSpeed(run, name())};
}

QStringList ExponentialModel::inputSignals(const RunData& run) const {
    if (!run.positionDependent()) return {run.spindle_speed_rpm.name};
    return {run.motion.empty() ? kFeedColumn : QStringLiteral("motion")};
}

}  // namespace driftlab::models
