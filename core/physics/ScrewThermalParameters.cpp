#include "core/physics/ScrewThermalParameters.h"

#include <stdexcept>
#include <string>

namespace driftlab::physics {

double ScrewThermalParameters::nutPower_W(double omega_rad_s) const {
    const double w = std::abs(omega_rad_s);
    if (nut_heat_exponent == 1) return c_nut_W_per_rad_s * w;
    return c_nut_W_per_rad_s * kReferenceSpeed_rad_s *
           std::pow(w / kReferenceSpeed_rad_s, nut_heat_exponent);
}

void ScrewThermalParameters::validate() const {
    auto positive = [](double value, const char* name) {
        if (!(value > 0) || !std::isfinite(value))
            throw std::invalid_argument(std::string("screw simulation: ") + name +
                                        " must be positive and finite, got " +
                                        std::to_string(value));
    };
    auto nonNegative = [](double value, const char* name) {
        if (!(value >= 0) || !std::isfinite(value))
            throw std::invalid_argument(std::string("screw simulation: ") + name +
                                        " must not be negative, got " + std::to_string(value));
    };
    positive(length_m, "length_m");
    positive(diameter_m, "diameter_m");
    positive(lead_m, "lead_m");
    positive(nut_length_m, "nut_length_m");
    positive(density_kg_m3, "density_kg_m3");
    positive(specific_heat_J_kgK, "specific_heat_J_kgK");
    positive(conductivity_W_mK, "conductivity_W_mK");
    positive(nut_heat_exponent, "nut_heat_exponent");
    positive(forced_exponent, "forced_exponent");
    nonNegative(c_nut_W_per_rad_s, "c_nut_W_per_rad_s");
    nonNegative(c_bearing_W_per_rad_s, "c_bearing_W_per_rad_s");
    nonNegative(c_motor_W_per_Nm2, "c_motor_W_per_Nm2");
    nonNegative(motor_entry_m, "motor_entry_m");
    nonNegative(h_W_m2K, "h_W_m2K");
    nonNegative(h1_forced_W_m2K, "h1_forced_W_m2K");
    if (!std::isfinite(alpha_per_K) || !std::isfinite(fixed_end_axis_mm))
        throw std::invalid_argument(
            "screw simulation: alpha_per_K and fixed_end_axis_mm must be finite");
    if (cells < 3)
        throw std::invalid_argument("screw simulation: at least 3 cells, got " +
                                    std::to_string(cells));
    if (!(theta >= 0.5 && theta <= 1))
        throw std::invalid_argument("screw simulation: theta must be in [0.5, 1], got " +
                                    std::to_string(theta));
}

}  // namespace driftlab::physics
