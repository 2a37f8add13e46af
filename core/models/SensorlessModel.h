#pragma once
// Sensorless model: the thermal error of a feed axis from its drive alone, no
// sensor on the machine. The screw simulation of docs/physics.md driven by
// what the controller and the drive know: the motion (nut and bearing friction
// heat ∝ screw speed) and the logged motor torque (motor heat ∝ torque², into
// the fixed end); c_nut, c_b and h are identified by Ceres on positioning
// errors only, and c_motor with them when a little motor heat lowers the cost.
// The room is the one temperature read, where logged (ISO 230-3 logs it for
// every test): the screw follows a swinging room, and no drive signal shows
// that; without it the room is held steady.
//
// Why physics rather than a regression on torque and speed (docs/models.md):
// the inertia torque of reversals heats the motor, not the nut, so the torque
// enters only where its heat goes; and the heat spreads over the stroke the
// nut runs, which a gain linear in position cannot follow from one state to
// another.

#include "core/models/HeatTransferModel.h"

namespace driftlab::models {

/// c_nut, c_b, h and c_motor: the heat-transfer model's coefficients and the
/// motor's heat per torque².
ScrewModelVariant sensorlessScrewModel();

class SensorlessModel final : public HeatTransferModel {
public:
    /// RoomInput::Steady makes the model blind to the room even where it is logged.
    explicit SensorlessModel(RoomInput room = RoomInput::RoomOnly);
    QString name() const override { return QStringLiteral("sensorless"); }
    QString describe() const override;

protected:
    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;
};

}  // namespace driftlab::models
