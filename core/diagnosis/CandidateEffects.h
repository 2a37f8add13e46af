#pragma once
// The library of candidate effects of docs/diagnosis.md: each a physical
// extension of the base heat-transfer model with the free parameters its
// physics needs (a speed exponent, a time constant, a sensitivity), refitted
// on the training runs by the same Ceres identification. Effects compose: the
// second pass of the diagnosis fits a candidate on top of an adopted one.

#include <functional>
#include <vector>

#include "core/models/HeatTransferModel.h"

namespace driftlab::diagnosis {

/// Built with designated initializers: only what an effect has is named.
struct CandidateEffect {
    QString cause;  ///< cause id: "forced_convection", "sensor_lag:T_nut", …
    /// The sensor of a `:channel` cause on the screw (its gain is on that
    /// sensor); empty: the gain is on positioning.
    QString channel = {};
    std::vector<models::FreeParameter> parameters;  ///< the effect's own
    /// How the effect's values (`own`, in `parameters` order) enter the
    /// simulation; empty for effects on the readings only.
    std::function<void(const double* own, physics::ScrewThermalParameters&)> physics = {};
    /// How they change the readings after the simulation; empty for effects
    /// on the physics only.
    std::function<void(const double* own, const models::ScrewRunInputs&,
                       const std::vector<models::PredictionPoint>&, models::ScrewRunOutputs&)>
        readings = {};
    /// How they change what drives the simulation (a late sensor's room,
    /// air or structure); empty for most.
    std::function<void(const double* own, models::ScrewRunInputs&)> inputs = {};
    /// For an effect on a sensor off the screw: what it measures ("room", …).
    QString measures = {};
    /// The cause it can only act through (a late air sensor through
    /// air_refraction): tested in the second step, on top of that cause.
    QString on_top_of = {};
    /// It changes only the readings (or the air and structure rises they
    /// read), not what the screw simulation computes: it is fitted on the
    /// step's simulation, with no new one (OutputEffectFit.h).
    bool output_only = false;
};

/// Every candidate the training runs can support, starting from the base fit
/// (c_nut, c_b, h) and its residuals on the training runs (for the starting
/// values of time constants): sensor effects for each sensor on the screw,
/// motor heat only with a torque column, air and frame effects only with an
/// air or structure channel.
std::vector<CandidateEffect> candidateEffects(
    const std::vector<models::RunData>& runs,
    const std::vector<models::ReadingResiduals>& baseResiduals);

/// The base model extended by `effects` in order; starting values are
/// `start` (base values, then each effect's, as a fit of the same extension
/// returns them) as far as it goes, then the parameters' own initial values.
models::ScrewModelVariant extendedModel(const std::vector<CandidateEffect>& effects,
                                        const std::vector<double>& start);

/// Edlén: the refractive index of air changes by −0.95 ppm per kelvin.
inline constexpr double kEdlen_ppm_per_K = -0.95;

}  // namespace driftlab::diagnosis
