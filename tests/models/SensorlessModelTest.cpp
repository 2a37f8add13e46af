// The sensorless model across the moving states of the rig: fitted on S1 from
// positioning errors, the motion and the motor torque alone, it must hold on
// every other state within 3× the heat-transfer model (issue 10), which reads
// the screw's sensors and the room. The one temperature it reads is the room's:
// a swinging room is the one thing no drive signal shows.
#include <gtest/gtest.h>

#include <QStringList>
#include <cmath>
#include <sstream>
#include <string>

#include "core/models/HeatTransferModel.h"
#include "core/models/ModelScore.h"
#include "core/models/SensorlessModel.h"
#include "core/rig/CampaignSimulator.h"

using namespace driftlab;

namespace {

/// S1 8000, S2 6500, S3 15000 mm/min on one range; S4, S5 other ranges.
std::vector<models::RunData> fiveStates(double roomSwing_K, double motorHeat_W_per_Nm2 = 0) {
    rig::RigSpec spec;
    spec.seed = 41;
    spec.environment.ambient_swing_K = roomSwing_K;
    spec.effects.motor_heat_W_per_Nm2 = motorHeat_W_per_Nm2;
    const Campaign campaign = rig::simulateCampaign(spec);
    QStringList ids;
    for (const auto& r : campaign.runs) ids << r.id;
    auto data = models::buildDataset(campaign, ids);
    EXPECT_TRUE(data.ok()) << qPrintable(data.error);
    return data.runs;
}

/// RMS on each run of `model` fitted on `train`; the fit into `fitted` if given.
std::vector<double> scoresOf(models::ThermalErrorModel& model, const models::RunData& train,
                             const std::vector<models::RunData>& runs,
                             models::FitSummary* fitted = nullptr) {
    const auto fit = model.fit({train});
    EXPECT_TRUE(fit.success) << qPrintable(fit.message);
    if (fitted) *fitted = fit;
    std::vector<double> rms;
    for (const auto& run : runs) {
        const models::Score score = models::scoreModel(model, {run});
        EXPECT_TRUE(score.ok()) << qPrintable(score.error);
        rms.push_back(score.rms_um);
    }
    return rms;
}

/// "label: 0.31 0.29 …", for a failure message.
std::string listed(const char* label, const std::vector<double>& rms) {
    std::ostringstream out;
    out << label << ":";
    for (double v : rms) out << " " << v;
    return out.str();
}

struct AgainstHeatTransfer {
    models::FitSummary sensorless_fit;
    std::vector<double> heat_transfer_rms_um;  ///< per state
};

/// Sensorless against heat-transfer, both fitted on S1: the ratio on every state.
AgainstHeatTransfer expectWithinThreeTimesHeatTransfer(const std::vector<models::RunData>& runs,
                                                       models::SensorlessModel& sensorless) {
    models::HeatTransferModel physics;
    AgainstHeatTransfer out;
    const auto blind = scoresOf(sensorless, runs[0], runs, &out.sensorless_fit);
    out.heat_transfer_rms_um = scoresOf(physics, runs[0], runs);
    SCOPED_TRACE(listed("fitted on S1, µm RMS on S1..S5; sensorless", blind) + "; " +
                 listed("heat-transfer", out.heat_transfer_rms_um));
    for (std::size_t s = 0; s < runs.size(); ++s)
        EXPECT_LT(blind[s], 3 * out.heat_transfer_rms_um[s])
            << "state " << runs[s].run_id.toStdString();
    return out;
}

}  // namespace

TEST(SensorlessModel, holdsOnEveryStateWithinThreeTimesHeatTransferWhenTheRoomIsSteady) {
    const auto runs = fiveStates(0);
    models::SensorlessModel sensorless;
    const auto fit = expectWithinThreeTimesHeatTransfer(runs, sensorless).sensorless_fit;
    // From positioning errors alone it finds the rig's heat: the nut's friction
    // torque, the convection, and no motor heat (the rig's drive has none).
    const physics::ScrewThermalParameters truth = rig::RigSpec{}.screw;
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("c_nut")).value, truth.c_nut_W_per_rad_s,
                0.15 * truth.c_nut_W_per_rad_s);
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("h")).value, truth.h_W_m2K, 0.15 * truth.h_W_m2K);
    EXPECT_LT(fit.parameters.at(QStringLiteral("c_motor")).value, 0.05);
    EXPECT_EQ(fit.inputs,
              QStringList({kTorqueColumn, QStringLiteral("motion"), QStringLiteral("T_ambient")}));
}

TEST(SensorlessModel, putsTheInertiaTorqueOfReversalsIntoTheMotorNotTheNut) {
    // Motor heat ∝ torque², and the fast state's reversals square up large
    // inertia torques: read as nut friction (the regression this model
    // replaced) they made S3 miss by 15 µm. Here they heat the fixed end.
    // The base heat-transfer model has no motor heat and misses S3 by ~14 µm;
    // the sensorless model stays at the interferometer's noise on every state.
    const double motorHeat = 1.0;
    const auto runs = fiveStates(0, motorHeat);
    models::SensorlessModel sensorless;
    const auto blind = scoresOf(sensorless, runs[0], runs);
    SCOPED_TRACE(listed("motor heat 1 W/(N·m)², fitted on S1, µm RMS on S1..S5", blind));
    // A cycle-0 difference of two readings, each with the rig's noise.
    const double noiseOfADifference_um = rig::InterferometerSpec{}.noise_um * std::sqrt(2.0);
    for (std::size_t s = 0; s < runs.size(); ++s)
        EXPECT_LT(blind[s], 1.5 * noiseOfADifference_um)
            << "state " << runs[s].run_id.toStdString();
    const auto fit = sensorless.fit({runs[0]});
    EXPECT_NEAR(fit.parameters.at(QStringLiteral("c_motor")).value, motorHeat, 0.3 * motorHeat);
}

TEST(SensorlessModel, readsTheRoomWhereItIsLoggedAndHoldsEveryStateUnderARoomSwing) {
    // The rig's default room swings 0.5 K over 12 h, and the screw follows it:
    // no drive signal shows that. Reading the room thermometer (which ISO 230-3
    // logs anyway; it is not on the machine) the model holds every state within
    // 3× heat-transfer; blind to it, the worst state misses by more than 2×, so
    // what the room costs is shown, not hidden.
    const auto runs = fiveStates(0.5);
    models::SensorlessModel sensorless;
    const auto withRoom = expectWithinThreeTimesHeatTransfer(runs, sensorless);
    EXPECT_TRUE(withRoom.sensorless_fit.inputs.contains(QStringLiteral("T_ambient")));

    models::SensorlessModel blindToTheRoom(models::RoomInput::Steady);
    models::FitSummary fit;
    const auto blind = scoresOf(blindToTheRoom, runs[0], runs, &fit);
    SCOPED_TRACE(listed("room swinging 0.5 K, fitted on S1, blind to the room", blind));
    double worstBlind = 0;
    for (std::size_t s = 0; s < runs.size(); ++s)
        worstBlind = std::max(worstBlind, blind[s] / withRoom.heat_transfer_rms_um[s]);
    EXPECT_GT(worstBlind, 2.0);
    EXPECT_EQ(fit.inputs, QStringList({kTorqueColumn, QStringLiteral("motion")}));
    EXPECT_EQ(fit.notes.filter(QStringLiteral("the room is taken as steady")).size(), 1);

    // A campaign that logs no room: held steady, and said.
    models::RunData noRoom = runs[0];
    std::erase_if(noRoom.temperatures,
                  [](const models::TemperatureRise& t) { return t.role == ChannelRole::Ambient; });
    models::SensorlessModel roomNotLogged;
    const auto steady = roomNotLogged.fit({noRoom});
    ASSERT_TRUE(steady.success) << qPrintable(steady.message);
    EXPECT_EQ(steady.notes.filter(QStringLiteral("no room temperature is logged")).size(), 1);
}

TEST(SensorlessModel, needsTheMotorTorque) {
    auto runs = fiveStates(0);
    runs[0].torque_Nm = {};
    runs[0].torque_Nm.name = kTorqueColumn;
    models::SensorlessModel model;
    const auto fit = model.fit({runs[0]});
    EXPECT_FALSE(fit.success);
    EXPECT_EQ(fit.message, QStringLiteral("model 'sensorless' needs the motor torque: run 'S1' has "
                                          "no samples in column 'torque_Nm'"));
}
