#pragma once
// Everything the screw simulation of docs/physics.md needs: geometry,
// material, heat-source coefficients, convection and numerics. SI units inside
// the physics (m, s, W, K); the axis coordinate of the fixed end is in mm
// because motion segments are logged in mm.

#include <cmath>

namespace driftlab::physics {

/// What happens at one end of the screw, besides the bearing heat that goes
/// into the end cell. Insulated is the machine case; the others exist so the
/// solver can be checked against textbook solutions.
struct EndCondition {
    enum class Kind { Insulated, FixedTemperature, HeatFlux };
    Kind kind = Kind::Insulated;
    double temperature_C = 20;  ///< FixedTemperature
    double heat_W = 0;          ///< HeatFlux, into the screw
};

struct ScrewThermalParameters {
    // Geometry
    double length_m = 0.9;
    double diameter_m = 0.04;
    double lead_m = 0.01;
    double nut_length_m = 0.08;
    double fixed_end_axis_mm = -40;  ///< axis coordinate of the fixed bearing; the screw runs to +x

    // Material (steel)
    double density_kg_m3 = 7850;
    double specific_heat_J_kgK = 460;
    double conductivity_W_mK = 45;
    double alpha_per_K = 11.5e-6;

    // Heat sources. ω is the screw speed in rad/s, ω = 2π·v/lead.
    double c_nut_W_per_rad_s = 0.11;      ///< nut friction power Q = c_nut·|ω| (n = 1)
    double nut_heat_exponent = 1;         ///< Q = c_nut·ω_ref·(|ω|/ω_ref)^n, equal at ω_ref
    double c_bearing_W_per_rad_s = 0.02;  ///< into each end cell, Q_b = c_b·|ω|
    double c_motor_W_per_Nm2 = 0;         ///< motor heat into the fixed end, ∝ torque²
    /// The motor's heat enters evenly over this length from the fixed end
    /// (through the coupling, flange and bearing seat); 0: the end cell.
    double motor_entry_m = 0;

    // Convection to ambient: h = h0 + h1·|ω|^m (h1 = 0 in the base model).
    double h_W_m2K = 12;
    double h1_forced_W_m2K = 0;  ///< per (rad/s)^m
    double forced_exponent = 1;

    // Numerics
    int cells = 200;
    double theta = 1.0;  ///< 1 = backward Euler, 0.5 = Crank–Nicolson
    EndCondition fixed_end;
    EndCondition free_end;

    /// Reference speed of the nut-heat exponent: 800 rpm.
    static constexpr double kReferenceSpeed_rad_s = 2 * M_PI * 800 / 60;

    double area_m2() const { return M_PI * diameter_m * diameter_m / 4; }
    double perimeter_m() const { return M_PI * diameter_m; }
    double cellWidth_m() const { return length_m / cells; }
    double screwSpeed_rad_s(double axisSpeed_m_s) const {
        return 2 * M_PI * std::abs(axisSpeed_m_s) / lead_m;
    }
    double nutPower_W(double omega_rad_s) const;

    /// Throws std::invalid_argument naming the first parameter that cannot be
    /// simulated (non-positive dimension or material constant, negative heat
    /// coefficient, θ outside [0.5, 1], fewer than 3 cells).
    void validate() const;
};

}  // namespace driftlab::physics
