#include "core/models/SensorlessModel.h"

#include <cmath>

#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {
namespace {

HeatTransferOptions sensorlessOptions(RoomInput room) {
    HeatTransferOptions options;
    options.fit_temperatures = false;
    options.room = room;
    return options;
}

/// A motor heat small against the nut's, to ask whether any helps, W/(N·m)².
constexpr double kMotorHeatProbe_W_per_Nm2 = 1e-3;

void requireTorque(const RunData& run) {
    if (run.torque_Nm.empty())
        throw ModelError(QStringLiteral("model 'sensorless' needs the motor torque: run '%1' has "
                                        "no samples in %2")
                             .arg(run.run_id, describeSignal(run.torque_Nm)));
}

}  // namespace

ScrewModelVariant sensorlessScrewModel() {
    ScrewModelVariant v = baseScrewModel();
    v.parameters.push_back({QStringLiteral("c_motor"), QStringLiteral("W/(N·m)²"), 0.05, 0, 5});
    v.physics = [base = v.physics](const double* p, physics::ScrewThermalParameters& s) {
        base(p, s);
        s.c_motor_W_per_Nm2 = p[3];
    };
    return v;
}

SensorlessModel::SensorlessModel(RoomInput room)
    : HeatTransferModel(sensorlessOptions(room), baseScrewModel()) {}

QString SensorlessModel::describe() const {
    return QStringLiteral(
        "No sensor on the machine: 1-D conduction along the screw, heated by the nut and "
        "bearings in proportion to the screw speed and by the motor in proportion to its "
        "torque², in the room's logged temperature (steady where none is logged); c_nut, c_b, "
        "h (and c_motor where motor heat helps) identified from positioning errors");
}

FitSummary SensorlessModel::fitRuns(const std::vector<RunData>& training) {
    // A drift target is refused by the simulation's own check, before the torque.
    for (const RunData& run : training)
        if (run.positionDependent()) requireTorque(run);
    // Without motor heat first. c_motor is then freed only when a little of it
    // lowers the cost: a bound-constrained solver crawls towards an optimum on
    // the bound (most axes, whose motor is not coupled to the screw).
    setVariant(baseScrewModel());
    FitSummary summary = HeatTransferModel::fitRuns(training);
    // The cost's slope in c_motor at 0, one-sided and to second order (the
    // curvature is large where c_b already warms the fixed end).
    ScrewModelVariant withMotor = sensorlessScrewModel();
    for (std::size_t i = 0; i < values().size(); ++i) withMotor.parameters[i].initial = values()[i];
    std::vector<double> at = values();
    at.push_back(0);
    setVariant(withMotor);
    auto costWithMotor = [&](double c_motor) {
        at.back() = c_motor;
        return cost(at, training);
    };
    // At c_motor = 0 the cost is the base fit's own.
    const double h = kMotorHeatProbe_W_per_Nm2;
    const double slope = (4 * costWithMotor(h) - costWithMotor(2 * h) -
                          3 * summary.metrics.at(QStringLiteral("final_cost"))) /
                         (2 * h);
    if (slope < 0) {
        summary = HeatTransferModel::fitRuns(training);
    } else {
        setVariant(baseScrewModel());
        summary.parameters[QStringLiteral("c_motor")] = {0, std::nan(""),
                                                         withMotor.parameters.back().unit};
        summary.notes << QStringLiteral(
            "no motor heat: heating the fixed end in proportion to the torque² makes the fit "
            "worse, c_motor = 0");
    }
    summary.inputs = QStringList{kTorqueColumn, QStringLiteral("motion")};
    const bool blind = options().room == RoomInput::Steady;
    if (const TemperatureRise* room = firstUsableOfRole(training.front(), ChannelRole::Ambient);
        room && !blind)
        summary.inputs << room->channel_id;
    else
        summary.notes << QStringLiteral(
                             "the room is taken as steady: %1 (1 K moves a point 1 m from the "
                             "fixed end by about %2 µm once the screw has followed)")
                             .arg(blind ? QStringLiteral("the model was asked not to read it")
                                        : QStringLiteral("no room temperature is logged"))
                             .arg(messageNumber(training.front().screw->alpha_per_K * 1e6));
    return summary;
}

Eigen::VectorXd SensorlessModel::predictRun(const RunData& run,
                                            const std::vector<PredictionPoint>& at) const {
    requireTorque(run);
    return HeatTransferModel::predictRun(run, at);
}

}  // namespace driftlab::models
