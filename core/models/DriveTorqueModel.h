#pragma once

namespace driftlab::models {

/// The axis drive's torque as the motion explains it (see DriveTorque.h):
/// τ = F_c·sgn ω + b·ω while the speed holds, plus what its changes cost.
struct DriveTorqueModel {
    double coulomb_Nm = 0;            ///< F_c
    double viscous_Nm_per_rad_s = 0;  ///< b
    /// J², the inertia torque's square per unit of α², (rad/s²)².
    double inertia_squared_kg2m4 = 0;
};

}  // namespace driftlab::models
