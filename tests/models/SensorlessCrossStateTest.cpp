// The sensorless model across moving states: the reversals of a fast state
// make inertia torque that is not friction heat. The inertia it separates is
// the rig drive's, and separating it shrinks the miss on the fastest state.
#include <gtest/gtest.h>

#include <QStringList>
#include <cmath>
#include <iostream>

#include "core/models/DriveFriction.h"
#include "core/models/HeatTransferModel.h"
#include "core/models/SensorlessModel.h"
#include "core/rig/CampaignSimulator.h"

using namespace driftlab;

namespace {

std::vector<models::RunData> fiveStates() {
    rig::RigSpec spec;
    spec.seed = 41;
    const Campaign campaign = rig::simulateCampaign(spec);
    QStringList ids;
    for (const auto& r : campaign.runs) ids << r.id;
    auto data = models::buildDataset(campaign, ids);
    EXPECT_TRUE(data.ok()) << qPrintable(data.error);
    return data.runs;
}

}  // namespace

TEST(SensorlessModel, separatesTheInertiaTorqueOfTheRigsDrive) {
    const rig::AxisDriveSpec drive;
    // J²/t_acc of the rig's drive: the inertia part of the logged mean-square
    // torque per (Δω)²/Δt. Recovered from the torque log and the motion alone.
    const double expected = drive.inertia_kg_m2 * drive.inertia_kg_m2 / drive.acceleration_time_s;
    const double fitted = models::fitInertiaTerm(fiveStates());
    EXPECT_NEAR(fitted, expected, 0.2 * expected);
}

/// RMS on each run of `model` fitted on `train`.
std::vector<double> scoresOf(models::ThermalErrorModel& model, const models::RunData& train,
                             const std::vector<models::RunData>& runs) {
    EXPECT_TRUE(model.fit({train}).success);
    std::vector<double> rms;
    for (const auto& run : runs) {
        const auto p = model.predict(run);
        EXPECT_TRUE(p.error.isEmpty()) << qPrintable(p.error);
        double squares = 0;
        const Eigen::VectorXd observed = run.observedErrors();
        for (Eigen::Index k = 0; k < observed.size(); ++k)
            squares += std::pow(observed(k) - p.error_um[std::size_t(k)], 2);
        rms.push_back(std::sqrt(squares / double(std::max<Eigen::Index>(1, observed.size()))));
    }
    return rms;
}

TEST(SensorlessModel, fittedOnS1NoLongerReadsTheFastStatesReversalsAsHeat) {
    const auto runs =
        fiveStates();  // S1 8000, S2 6500, S3 15000 mm/min on one range; S4, S5 other ranges
    models::SensorlessModel separated, raw({}, false);
    models::HeatTransferModel physics;
    const auto withInertia = scoresOf(separated, runs[0], runs);
    const auto withoutInertia = scoresOf(raw, runs[0], runs);
    const auto reference = scoresOf(physics, runs[0], runs);
    std::cout << "fitted on S1, µm RMS on S1..S5\n  inertia separated:";
    for (double v : withInertia) std::cout << " " << v;
    std::cout << "\n  torque as friction:";
    for (double v : withoutInertia) std::cout << " " << v;
    std::cout << "\n  heat-transfer:     ";
    for (double v : reference) std::cout << " " << v;
    std::cout << "\n";
    // The fastest state (S3, almost twice S1's feed) is where the reversals'
    // inertia torque misleads: separated, the miss shrinks by a third or more.
    // It is still far from physics (issue 10 asks for 3×): one state cannot
    // tell friction power from speed, and the gain is linear in position.
    EXPECT_LT(withInertia[2], 0.7 * withoutInertia[2]);
    EXPECT_GT(withInertia[2], reference[2]);
}
