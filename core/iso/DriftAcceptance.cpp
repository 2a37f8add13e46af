#include "core/iso/DriftAcceptance.h"

#include <algorithm>
#include <cmath>

namespace driftlab::iso {

namespace {

void include(DriftFigures& figures, const DriftSeries& series) {
    figures.max_drift_um = std::max(figures.max_drift_um, std::abs(series.max_drift_um));
    figures.drift_range_um = std::max(figures.drift_range_um, series.range_um);
}

}  // namespace

DriftFigures driftFigures(const AxisDriftEvaluation& evaluation) {
    DriftFigures figures;
    for (const TargetDrift& t : evaluation.targets) include(figures, t.drift);
    return figures;
}

DriftFigures driftFigures(const ProbeDriftEvaluation& evaluation) {
    DriftFigures figures;
    for (const ProbeDrift& p : evaluation.probes) include(figures, p.drift);
    return figures;
}

double driftExpandedUncertainty_um(const SetupUncertainty& setup) {
    const double device_um = setup.device_um / setup.device_k;
    const double eve_um = setup.eve_um.value_or(0) / (2 * std::sqrt(3.0));
    return setup.coverage_k * std::hypot(device_um, eve_um);
}

std::vector<Decision> driftDecisions(const AcceptanceSpecification& specification,
                                     const QString& axis, const DriftFigures& figures) {
    std::vector<Decision> decisions;
    const AxisTolerances* tolerances = specification.tolerancesOf(axis);
    if (!tolerances) return decisions;
    const double U_um = driftExpandedUncertainty_um(specification.uncertainty);
    for (const QString& key : iso230_3ParameterKeys()) {
        const auto t = tolerances->iso230_3_um.find(key);
        if (t == tolerances->iso230_3_um.end()) continue;
        const double value_um =
            key == QLatin1String("max_drift") ? figures.max_drift_um : figures.drift_range_um;
        decisions.push_back(decide(key, value_um, U_um, t->second));
    }
    return decisions;
}

}  // namespace driftlab::iso
