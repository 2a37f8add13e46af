#pragma once
// One-dimensional transient conduction along the ball screw (docs/physics.md),
// finite volumes with implicit θ-stepping:
//
//   ρ c A ∂T/∂t = k A ∂²T/∂x² − h P (T − T_amb(t)) + q_nut(x,t) + q_bearings(x,t)
//
// It runs online: step() advances by one sample interval in O(cells), so a
// live observer never re-simulates from zero. Every joule is booked (heat in,
// stored, convected, through fixed-temperature ends) so a run can be checked
// for energy balance.

#include <array>
#include <span>
#include <vector>

#include "core/domain/Run.h"
#include "core/physics/NutPath.h"
#include "core/physics/ScrewThermalParameters.h"
#include "core/physics/TridiagonalSolver.h"

namespace driftlab::physics {

/// What acts on the screw during one step.
struct StepConditions {
    double dt_s = 1;
    double ambient_begin_C = 20;  ///< ambient at the start of the step
    double ambient_end_C = 20;    ///< and at its end (linear in between)
    /// The axis motion (axis mm, absolute s); only the part inside the step is
    /// used, so the whole run's segments may be passed every step.
    std::span<const MotionSegment> motion;
    /// The same motion cut once for many simulations of one run (NutPath::fits
    /// this screw and step), and this step's index in it; `motion` is then not read.
    const NutPath* nut_path = nullptr;
    std::size_t nut_path_step = 0;
    double mean_torque_squared_Nm2 = 0;  ///< mean of torque² over the step, motor heat
};

/// Joules since construction. Balance: heat_in = stored + convected + through_ends.
struct EnergyLedger {
    double nut_J = 0;
    double bearings_J = 0;
    double motor_J = 0;
    double end_flux_J = 0;      ///< HeatFlux end conditions
    double convected_J = 0;     ///< to ambient, positive out of the screw
    double through_ends_J = 0;  ///< out through FixedTemperature ends
    double heatIn_J() const { return nut_J + bearings_J + motor_J + end_flux_J; }
};

class ScrewThermalModel {
public:
    /// Uniform initial temperature. Throws std::invalid_argument on parameters
    /// that cannot be simulated.
    ScrewThermalModel(const ScrewThermalParameters& parameters, double initial_C);

    /// Advances by conditions.dt_s. Throws std::invalid_argument on a
    /// non-positive or non-finite step or ambient, or motion that leaves the
    /// screw (nut centre beyond either end).
    void step(const StepConditions& conditions);

    double time_s() const { return m_time_s; }
    const ScrewThermalParameters& parameters() const { return m_parameters; }
    /// Cell temperatures, cell i centred at (i + ½)·Δx from the fixed end.
    const std::vector<double>& temperatures_C() const { return m_temperature; }
    double cellCentre_m(int cell) const { return (cell + 0.5) * m_dx; }

    /// Temperature at a screw coordinate, linear between cell centres.
    double temperatureAt_C(double x_m) const;
    /// Mean temperature over [from, to] (screw coordinates): the nut-flank
    /// sensor reads the screw under the nut.
    double meanTemperature_C(double from_m, double to_m) const;
    /// The screw under the nut centred at an axis position.
    double temperatureUnderNut_C(double axis_mm) const;

    /// Thermal error at an axis position: E = ∫ α (T − T_ref) ds from the fixed
    /// end, µm. T_ref is the initial field (or the one set by resetReference()).
    double thermalError_um(double axis_mm) const;
    /// Many positions at once: one O(cells) prefix sum, then O(1) per position.
    std::vector<double> thermalError_um(const std::vector<double>& axis_mm) const;
    void resetReference();

    double screwCoordinate_m(double axis_mm) const {
        return (axis_mm - m_parameters.fixed_end_axis_mm) * 1e-3;
    }
    /// Heat stored since construction, J (the ledger's "stored").
    double storedEnergy_J() const;
    const EnergyLedger& energy() const { return m_ledger; }

private:
    void refactorise(double dt_s, double h_W_m2K);
    double collectMotionHeat(const StepConditions& c, double t0, double t1);
    double heatBearings(double omega_rad_s, double duration_s, double forcedPower);
    /// The powers of a screw speed the step needs: the nut's power and
    /// |ω|^m for forced convection.
    struct SpeedTerms {
        double omega_rad_s = -1;
        double nut_W = 0;
        double forced = 0;  ///< |ω|^m, 0 without forced convection
    };
    const SpeedTerms& speedTerms(double omega_rad_s);
    /// `joules` into the cells over `length_m` from the fixed end, in
    /// proportion to each cell's share of it (the end cell for 0).
    void depositAtFixedEnd(double joules, double length_m);
    double cumulativeExpansion_m(double x_m, const std::vector<double>& prefix) const;
    std::vector<double> expansionPrefix() const;

    ScrewThermalParameters m_parameters;
    int n_;
    double m_dx;
    double m_capacity_J_K;        ///< per cell
    double m_conductance_W_K;     ///< between neighbouring cells
    double m_endConductance_W_K;  ///< cell centre to a fixed-temperature end face
    double m_surface_m2;          ///< per cell
    double m_time_s = 0;
    std::size_t m_motionCursor = 0;
    std::vector<MotionPiece> m_pieces;  ///< of the current step, without a NutPath

    std::vector<double> m_temperature;
    std::vector<double> m_reference;  ///< for the thermal error
    std::vector<double> m_initial;    ///< for the energy ledger
    std::vector<double> m_source_J;   ///< heat deposited in the current step, per cell
    std::vector<double> m_rhs;
    double m_temperatureSum = 0;  ///< Σ T of the current field, for the ledger

    // A step holds many pieces at the same few speeds (every stroke at the
    // feed, in both directions), and std::pow was a quarter of a simulation:
    // the last speeds' terms are kept, exact since the inputs are the same.
    std::array<SpeedTerms, 4> m_speedTerms{};
    std::size_t m_nextSpeedTerm = 0;
    // Refactorisation's matrix, kept: forced convection refactorises every step.
    std::vector<double> m_lower, m_diag, m_upper;

    TridiagonalSolver m_solver;
    double m_factorisedDt = -1;
    double m_factorisedH = -1;
    EnergyLedger m_ledger;
};

}  // namespace driftlab::physics
