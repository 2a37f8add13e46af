#include "core/models/SensorlessModel.h"

#include "core/models/HeatSourceInputs.h"
#include "core/models/ModelError.h"

namespace driftlab::models {

SensorlessModel::SensorlessModel(LagSearchOptions search)
    : LagModel({{QStringLiteral("power"), 0, QStringLiteral("W")},
                {QStringLiteral("speed"), 1, QStringLiteral("rad/s")}},
               search) {}

QString SensorlessModel::describe() const {
    return QStringLiteral(
        "No temperature sensor: the motor's friction power |torque·ω| and the "
        "screw speed, each through a first-order thermal lag, with a gain linear "
        "in position.");
}

std::vector<PiecewiseInput> SensorlessModel::inputs(const RunData& run, double until_s) const {
    if (!run.positionDependent())
        throw ModelError(QStringLiteral("model 'sensorless' predicts the positioning error of a "
                                        "feed axis from its motor; it cannot predict channel '%1'")
                             .arg(run.target_channel));
    return {motorPower(run, until_s, name()), screwSpeedFromFeed(run, until_s, name())};
}

QStringList SensorlessModel::inputSignals(const RunData&) const {
    return {kTorqueColumn, kFeedColumn};
}

}  // namespace driftlab::models
