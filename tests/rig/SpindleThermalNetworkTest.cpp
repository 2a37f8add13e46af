// The spindle head's thermal network against closed forms: the steady state
// −A⁻¹·B·u, exact stepping (the same state whatever the step), a single node's
// first-order response, the drift lagging every sensor, and the simulator's
// noise-free twin.

#include <gtest/gtest.h>
#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>

#include "core/rig/SpindleTestSimulator.h"
#include "core/rig/SpindleThermalNetwork.h"

namespace driftlab::rig {
namespace {

TEST(SpindleThermalNetwork, settlesAtTheSteadyStateOfTheLinearSystem) {
    SpindleThermalNetwork head(20, 10);
    for (int k = 0; k < 100 * 3600 / 10; ++k) head.step(8000, 20);  // 100 h ≫ 3 h column core
    const auto heat = SpindleThermalNetwork::heatTerms_K(8000);
    const Eigen::Vector3d u(20, heat[0], heat[1]);
    const Eigen::Matrix<double, kSpindleNodes, 1> steady =
        -SpindleThermalNetwork::systemMatrix().partialPivLu().solve(
            SpindleThermalNetwork::inputMatrix() * u);
    for (int i = 0; i < kSpindleNodes; ++i)
        EXPECT_NEAR(head.temperature_C(SpindleNode(i)), steady[i], 1e-6) << i;
    // Heat flows down the chain: the bearing seat is warmest, the column core
    // above the room but the coolest of the head's nodes.
    EXPECT_GT(steady[int(SpindleNode::FrontBearing)], steady[int(SpindleNode::Housing)]);
    EXPECT_GT(steady[int(SpindleNode::ColumnCore)], 20.5);
    EXPECT_LT(steady[int(SpindleNode::ColumnCore)], steady[int(SpindleNode::ColumnSkin)]);
}

TEST(SpindleThermalNetwork, stepsExactlyWhateverTheStep) {
    SpindleThermalNetwork coarse(20, 60), fine(20, 1);
    for (int k = 0; k < 120; ++k) {  // 2 h at 6000 rpm in a room rising 1 K/h (held per minute)
        const double room = 20 + (k + 0.5) / 60.0;
        coarse.step(6000, room);
        for (int j = 0; j < 60; ++j) fine.step(6000, room);
    }
    for (int i = 0; i < kSpindleNodes; ++i)
        EXPECT_NEAR(coarse.temperature_C(SpindleNode(i)), fine.temperature_C(SpindleNode(i)), 1e-9)
            << i;
}

TEST(SpindleThermalNetwork, theMotorNodeAloneIsAFirstOrderLag) {
    // The stator has no neighbour: T(t) = room + q·(1 − exp(−t/τ)).
    SpindleThermalNetwork head(20, 5);
    const double tau = SpindleThermalNetwork::timeConstant_s(SpindleNode::Motor);
    const double q = SpindleThermalNetwork::heatTerms_K(9000)[1];
    for (int k = 1; k <= 720; ++k) {
        head.step(9000, 20);
        if (k % 120 == 0) {
            EXPECT_NEAR(head.temperature_C(SpindleNode::Motor),
                        20 + q * -std::expm1(-5.0 * k / tau), 1e-9);
        }
    }
}

TEST(SpindleThermalNetwork, theDriftIsNoFunctionOfTheSensorsCurrentReadings) {
    // The probes see mostly the shaft and the column core, which no sensor is
    // on: least squares of the z drift on all five sensors' current readings
    // leaves hysteresis far above the probes' 0.1 µm noise.
    std::vector<QString> columns;
    for (const Channel& c : spindleTestChannels()) columns.push_back(c.id);
    columns.push_back(QStringLiteral("T_ambient"));
    const driftlab::Run run = simulateSpindleTest(spindleTestProgramme(1), columns);
    auto column = [&](const QString& id) {
        const auto& v = run.samples.values[std::size_t(run.samples.columnIndex(id))];
        return Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size()));
    };
    const Eigen::VectorXd z = column(QStringLiteral("D_z"));
    Eigen::MatrixXd X(z.size(), 6);
    int k = 0;
    for (const Channel& c : spindleTestChannels())
        if (c.quantity == Quantity::Temperature) X.col(k++) = column(c.id);
    ASSERT_EQ(k, 5);
    X.col(5).setOnes();
    const Eigen::VectorXd residual = z - X * X.colPivHouseholderQr().solve(z);
    const double rms_um = std::sqrt(residual.squaredNorm() / double(z.size()));
    EXPECT_GT(rms_um, 1.0);
    EXPECT_LT(z.minCoeff(), -15);  // against tens of µm of drift
}

TEST(SpindleTestSimulator, aNoiseFreeTwinReadsTheSameThermometersAndTheProbesDrift) {
    // The tests' perfect model: the same run with probe_noise_um = 0 keeps
    // every thermometer reading and leaves the probes' drift without its
    // noise, so noisy − noise-free is the noise alone: mean 0, σ 0.1 µm.
    std::vector<QString> columns;
    for (const Channel& c : spindleTestChannels()) columns.push_back(c.id);
    SpindleTestSpec spec = spindleTestProgramme(2);
    const driftlab::Run noisy = simulateSpindleTest(spec, columns);
    spec.probe_noise_um = 0;
    const driftlab::Run twin = simulateSpindleTest(spec, columns);
    ASSERT_EQ(noisy.samples.time_s, twin.samples.time_s);
    for (const Channel& c : spindleTestChannels()) {
        const auto k = std::size_t(noisy.samples.columnIndex(c.id));
        const std::vector<double>& a = noisy.samples.values[k];
        const std::vector<double>& b = twin.samples.values[k];
        if (c.quantity != Quantity::Displacement) {
            EXPECT_EQ(a, b) << qPrintable(c.id);
            continue;
        }
        double sum = 0, squares = 0, roughness = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            sum += a[i] - b[i];
            squares += (a[i] - b[i]) * (a[i] - b[i]);
            if (i >= 2) roughness = std::max(roughness, std::abs(b[i] - 2 * b[i - 1] + b[i - 2]));
        }
        const double n = double(a.size()), mean = sum / n;
        EXPECT_NEAR(mean, 0, 0.01) << qPrintable(c.id);  // σ/√n ≈ 0.001 µm
        EXPECT_NEAR(std::sqrt(squares / n - mean * mean), 0.1, 0.005) << qPrintable(c.id);
        // The twin's drift is smooth: no 5 s step bends it by more than the
        // probes' 1 nm resolution and a speed change's kink.
        EXPECT_LT(roughness, 0.05) << qPrintable(c.id);
    }
}

TEST(SpindleTestProgrammes, eachRunHasItsOwnSpeedsAndEndsAtRest) {
    std::vector<std::vector<SpeedBlock>> seen;
    for (int k = 1; k <= 7; ++k) {
        const SpindleTestSpec spec = spindleTestProgramme(k);
        EXPECT_EQ(spec.run_id, QStringLiteral("SP%1").arg(k));
        EXPECT_EQ(spec.blocks.back().speed_rpm, 0) << k;
        for (const auto& other : seen) {
            bool same = other.size() == spec.blocks.size();
            for (std::size_t b = 0; same && b < other.size(); ++b)
                same = other[b].duration_s == spec.blocks[b].duration_s &&
                       other[b].speed_rpm == spec.blocks[b].speed_rpm;
            EXPECT_FALSE(same) << "programme " << k << " repeats an earlier one";
        }
        seen.push_back(spec.blocks);
    }
}

}  // namespace
}  // namespace driftlab::rig
