#include "core/rig/SpindleThermalNetwork.h"

#include <Eigen/LU>
#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

namespace driftlab::rig {
namespace {

using N = SpindleNode;

struct Coupling {
    N from;
    double weight;
};

struct NodeSpec {
    double tau_s;
    std::array<Coupling, 2> couplings;  ///< weight 0: unused
};

// Time constants and couplings of a machining-centre head on a column: the
// bearing seat is fast, the motor and shaft take tens of minutes, the column
// hours. The weights make the z drift tens of µm at 9000 rpm, as on real
// spindles, and let most of it relax within an hour of a stop.
const std::array<NodeSpec, kSpindleNodes>& nodes() {
    static const std::array<NodeSpec, kSpindleNodes> spec{{
        {400, {{{N::Shaft, 0.15}, {N::Shaft, 0}}}},             // FrontBearing
        {600, {{{N::Shaft, 0}, {N::Shaft, 0}}}},                // Motor
        {3000, {{{N::FrontBearing, 0.55}, {N::Motor, 0.4}}}},   // Shaft
        {700, {{{N::FrontBearing, 0.7}, {N::Motor, 0.1}}}},     // Housing
        {900, {{{N::Motor, 0.5}, {N::Housing, 0.2}}}},          // Headstock
        {1200, {{{N::Housing, 0.35}, {N::Headstock, 0.35}}}},   // ColumnSkin
        {10800, {{{N::ColumnSkin, 0.9}, {N::ColumnSkin, 0}}}},  // ColumnCore
    }};
    return spec;
}

constexpr double kBearingHeatAt10000rpm_K = 16;
constexpr double kMotorHeatAt10000rpm_K = 10;

}  // namespace

double SpindleThermalNetwork::timeConstant_s(SpindleNode node) {
    return nodes()[int(node)].tau_s;
}

std::array<double, 2> SpindleThermalNetwork::heatTerms_K(double speed_rpm) {
    const double n = std::abs(speed_rpm) / 10000.0;
    return {kBearingHeatAt10000rpm_K * std::pow(n, 1.4), kMotorHeatAt10000rpm_K * n * n};
}

Eigen::Matrix<double, kSpindleNodes, kSpindleNodes> SpindleThermalNetwork::systemMatrix() {
    Eigen::Matrix<double, kSpindleNodes, kSpindleNodes> A =
        -Eigen::Matrix<double, kSpindleNodes, kSpindleNodes>::Identity();
    for (int i = 0; i < kSpindleNodes; ++i) {
        for (const Coupling& c : nodes()[i].couplings) A(i, int(c.from)) += c.weight;
        A.row(i) /= nodes()[i].tau_s;
    }
    return A;
}

Eigen::Matrix<double, kSpindleNodes, 3> SpindleThermalNetwork::inputMatrix() {
    Eigen::Matrix<double, kSpindleNodes, 3> B = Eigen::Matrix<double, kSpindleNodes, 3>::Zero();
    for (int i = 0; i < kSpindleNodes; ++i) {
        double toNeighbours = 0;
        for (const Coupling& c : nodes()[i].couplings) toNeighbours += c.weight;
        B(i, 0) = (1 - toNeighbours) / nodes()[i].tau_s;  // the room's share
    }
    B(int(N::FrontBearing), 1) = 1 / nodes()[int(N::FrontBearing)].tau_s;
    B(int(N::Motor), 2) = 1 / nodes()[int(N::Motor)].tau_s;
    return B;
}

SpindleThermalNetwork::SpindleThermalNetwork(double room_C, double step_s) {
    m_temperature_C.setConstant(room_C);
    const auto A = systemMatrix();
    const Eigen::Matrix<double, kSpindleNodes, kSpindleNodes> Adt = A * step_s;
    m_transition = Adt.exp();
    // A is invertible: every node loses heat to the room, directly or through others.
    m_inputGain =
        A.partialPivLu().solve(m_transition - decltype(m_transition)::Identity()) * inputMatrix();
}

void SpindleThermalNetwork::step(double speed_rpm, double room_C) {
    const auto heat = heatTerms_K(speed_rpm);
    const Eigen::Vector3d u(room_C, heat[0], heat[1]);
    m_temperature_C = m_transition * m_temperature_C + m_inputGain * u;
}

}  // namespace driftlab::rig
