#include "core/models/SensorlessModel.h"

#include "core/models/DriveFriction.h"
#include "core/models/HeatSourceInputs.h"
#include "core/models/ModelError.h"

#include <limits>

namespace driftlab::models {

SensorlessModel::SensorlessModel(LagSearchOptions search, bool separateInertia)
    : LagModel({{QStringLiteral("power"), 0, QStringLiteral("W")},
                {QStringLiteral("speed"), 1, QStringLiteral("rad/s")}},
               search),
      separate_inertia_(separateInertia) {}

QString SensorlessModel::describe() const {
    return QStringLiteral(
        "No temperature sensor: the motor's friction power |torque·ω|, with the "
        "inertia torque of reversals taken out, and the screw speed, each through "
        "a first-order thermal lag, with a gain linear in position.");
}

std::vector<PiecewiseInput> SensorlessModel::inputs(const RunData& run, double until_s) const {
    if (!run.positionDependent())
        throw ModelError(QStringLiteral("model 'sensorless' predicts the positioning error of a "
                                        "feed axis from its motor; it cannot predict channel '%1'")
                             .arg(run.target_channel));
    PiecewiseInput speed = screwSpeedFromFeed(run, until_s, name());
    PiecewiseInput power = frictionPower(run, speed, until_s, inertia_term_, name());
    return {std::move(power), std::move(speed)};
}

FitSummary SensorlessModel::fitRuns(const std::vector<RunData>& training) {
    inertia_term_ = separate_inertia_ ? fitInertiaTerm(training) : 0;
    FitSummary summary = LagModel::fitRuns(training);
    summary.parameters[QStringLiteral("inertia_term")] = {
        inertia_term_, std::numeric_limits<double>::quiet_NaN(), QStringLiteral("N²·m²·s")};
    if (inertia_term_ == 0)
        summary.notes << QStringLiteral(
            "no inertia torque separated (no motion programme, or none in the torque): the "
            "logged torque is read as friction throughout");
    return summary;
}

QStringList SensorlessModel::inputSignals(const RunData&) const {
    return {kTorqueColumn, kFeedColumn};
}

}  // namespace driftlab::models
