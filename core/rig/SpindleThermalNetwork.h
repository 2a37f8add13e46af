#pragma once
// The thermal network of the simulated spindle head and column: lumped nodes,
// each relaxing with its own time constant towards a mix of its neighbours and
// the room, heated by bearing friction (∝ n^1.4) and motor losses (∝ n²).
// Two nodes carry no sensor, as on a real machine: the spindle shaft (heated
// through the bearings and the rotor) and the column core. The drift probes see
// mostly those, so the drift lags every sensor; a model on the current
// temperatures alone shows hysteresis, one with lagged inputs does not.
//
// Node i obeys τ_i·dT_i/dt = T_room + Σ_j c_ij·(T_j − T_room) + q_i(n) − T_i,
// a linear system dT/dt = A·T + B·u with u = (T_room, bearing heat, motor heat),
// stepped exactly (matrix exponential) for inputs held over each interval.

#include <Eigen/Core>
#include <array>

namespace driftlab::rig {

enum class SpindleNode : int {
    FrontBearing,  ///< bearing seat at the spindle nose (sensor T_spindle_bearing)
    Motor,         ///< motor stator (sensor T_spindle_motor)
    Shaft,         ///< spindle shaft: no sensor
    Housing,       ///< housing skin at the front (sensor T_spindle)
    Headstock,     ///< headstock rear (sensor T_headstock)
    ColumnSkin,    ///< column surface beside the headstock (sensor T_column)
    ColumnCore,    ///< column core: no sensor
};
inline constexpr int kSpindleNodes = 7;

class SpindleThermalNetwork {
public:
    /// All nodes at `room_C`; `step_s` is the fixed interval of step().
    SpindleThermalNetwork(double room_C, double step_s);

    /// Advances one interval with the speed and the room temperature held.
    void step(double speed_rpm, double room_C);
    double temperature_C(SpindleNode node) const { return m_temperature_C[int(node)]; }

    /// The node's time constant and the steady rise of the heated nodes, for
    /// the tests that check the stepping against closed forms.
    static double timeConstant_s(SpindleNode node);
    /// Steady heat terms q (K) of the front bearing and the motor at a speed.
    static std::array<double, 2> heatTerms_K(double speed_rpm);
    /// dT/dt = A·T + B·u: the system matrices (u = room, bearing, motor).
    static Eigen::Matrix<double, kSpindleNodes, kSpindleNodes> systemMatrix();
    static Eigen::Matrix<double, kSpindleNodes, 3> inputMatrix();

private:
    Eigen::Matrix<double, kSpindleNodes, 1> m_temperature_C;
    Eigen::Matrix<double, kSpindleNodes, kSpindleNodes> m_transition;  ///< exp(A·Δt)
    Eigen::Matrix<double, kSpindleNodes, 3> m_inputGain;  ///< A⁻¹·(exp(A·Δt) − I)·B
};

}  // namespace driftlab::rig
