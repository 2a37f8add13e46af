#pragma once
// Shared set-ups of the verification tests: a steel rod with the textbook fin
// quantities, steady-state stepping, reciprocating motion and printing of the
// observed numbers (they go into the test output and docs/physics.md).

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "core/domain/Run.h"
#include "core/physics/ScrewThermalModel.h"

namespace driftlab::physics::test {

/// A bare steel rod: the default screw geometry and material, no heat sources,
/// both ends insulated, the fixed end at axis 0 mm so axis mm = screw mm.
inline ScrewThermalParameters bareRod(double length_m, int cells) {
    ScrewThermalParameters p;
    p.length_m = length_m;
    p.cells = cells;
    p.fixed_end_axis_mm = 0;
    p.c_nut_W_per_rad_s = 0;
    p.c_bearing_W_per_rad_s = 0;
    return p;
}

/// Fin parameter m = sqrt(hP/(kA)), 1/m.
inline double finM(const ScrewThermalParameters& p) {
    return std::sqrt(p.h_W_m2K * p.perimeter_m() / (p.conductivity_W_mK * p.area_m2()));
}

/// Thermal diffusivity k/(ρc), m²/s.
inline double diffusivity(const ScrewThermalParameters& p) {
    return p.conductivity_W_mK / (p.density_kg_m3 * p.specific_heat_J_kgK);
}

/// Backward Euler is L-stable: a step of 1e9 s damps every mode by at least
/// (1 + 1e9 s / 3000 s)⁻¹ ≈ 3e-6, so a few such steps leave the discrete
/// steady state to round-off. The model must have theta = 1.
inline void stepToSteadyState(ScrewThermalModel& model, double ambient_C) {
    StepConditions c;
    c.dt_s = 1e9;
    c.ambient_begin_C = c.ambient_end_C = ambient_C;
    for (int i = 0; i < 6; ++i) model.step(c);
}

/// Reciprocation between two axis positions at a constant feed from start_s
/// for duration_s; the last stroke is cut at the end. Reversals take no time,
/// so the nut moves (and heats) all the time.
inline void appendReciprocation(std::vector<MotionSegment>& motion, double from_mm, double to_mm,
                                double feed_mm_min, double start_s, double duration_s) {
    const double strokeTime = std::abs(to_mm - from_mm) / feed_mm_min * 60;
    const double end = start_s + duration_s;
    double t = start_s;
    double a = from_mm;
    double b = to_mm;
    while (t < end - 1e-12) {
        const double t1 = std::min(end, t + strokeTime);
        const double reached = a + (b - a) * (t1 - t) / strokeTime;
        motion.push_back({t, t1, a, reached, (b > a ? 1 : -1) * feed_mm_min});
        t = t1;
        std::swap(a, b);
    }
}

inline void appendDwell(std::vector<MotionSegment>& motion, double at_mm, double start_s,
                        double duration_s) {
    motion.push_back({start_s, start_s + duration_s, at_mm, at_mm, 0});
}

/// Steps with a constant step and ambient through [0, duration) passing the
/// whole motion every step, as the campaign simulator does.
inline void runFor(ScrewThermalModel& model, const std::vector<MotionSegment>& motion, double dt_s,
                   double duration_s, double ambient_C) {
    StepConditions c;
    c.dt_s = dt_s;
    c.ambient_begin_C = c.ambient_end_C = ambient_C;
    c.motion = motion;
    const auto steps = static_cast<long>(std::llround(duration_s / dt_s));
    for (long i = 0; i < steps; ++i) model.step(c);
}

/// Observed order of convergence from errors at successive refinements by 2.
inline double observedOrder(double coarseError, double fineError) {
    return std::log2(coarseError / fineError);
}

/// Attaches observed figures to the test's report (--gtest_output=xml/json),
/// where docs/validation.md's generator and a reader find them.
inline void report(const std::string& key, const std::string& text) {
    ::testing::Test::RecordProperty(key, text);
}

inline std::string format(double value) {
    std::ostringstream out;
    out.precision(3);
    out << value;
    return out.str();
}

}  // namespace driftlab::physics::test
