#pragma once
// The library of candidate effects of DESIGN.md section 6: each a physical
// extension of the base heat-transfer model by one parameter, refitted on the
// training runs by the same Ceres identification.

#include <vector>

#include "core/models/HeatTransferModel.h"

namespace driftlab::diagnosis {

struct CandidateEffect {
    QString cause;                      ///< cause id: "forced_convection", "sensor_lag:T_nut", …
    QString channel;                    ///< the sensor of a `:channel` cause
    models::ScrewModelVariant variant;  ///< base parameters, then the effect's one
    models::FreeParameter parameter;    ///< the effect's parameter (last in the variant)
};

/// Every candidate the training runs can support, starting from the base fit
/// `baseValues` (c_nut, c_b, h): sensor effects for each sensor on the screw,
/// motor heat only with a torque column, air and frame effects only with an
/// air or structure channel.
std::vector<CandidateEffect> candidateEffects(const std::vector<models::RunData>& runs,
                                              const std::vector<double>& baseValues);

/// Edlén: the refractive index of air changes by −0.95 ppm per kelvin.
inline constexpr double kEdlen_ppm_per_K = -0.95;

}  // namespace driftlab::diagnosis
