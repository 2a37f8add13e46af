// Steady states against closed-form conduction–convection solutions (fins).
// θ = T − T_ambient, m = sqrt(hP/(kA)); every reference below is analytic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/physics/ScrewThermalModel.h"
#include "tests/physics/PhysicsTestSupport.h"

namespace driftlab::physics {
namespace {

using test::bareRod;
using test::finM;
using Kind = EndCondition::Kind;

constexpr double kAmbient = 20;

/// Largest deviation of the cell-centre temperatures from θ_exact(x), K.
template <typename Exact>
double maxError(const ScrewThermalModel& model, Exact exact) {
    double worst = 0;
    const auto& T = model.temperatures_C();
    for (int i = 0; i < static_cast<int>(T.size()); ++i)
        worst = std::max(worst, std::abs(T[static_cast<std::size_t>(i)] - kAmbient -
                                         exact(model.cellCentre_m(i))));
    return worst;
}

// Fin of length L with its base held at T_b and an insulated tip:
// θ(x) = θ_b cosh(m(L − x)) / cosh(mL), base heat Q = kA m θ_b tanh(mL).
TEST(SteadyState, FinWithFixedBaseFollowsCoshProfile) {
    ScrewThermalParameters p = bareRod(0.9, 200);
    const double thetaB = 50;
    p.fixed_end = {Kind::FixedTemperature, kAmbient + thetaB, 0};
    ScrewThermalModel model(p, kAmbient);
    test::stepToSteadyState(model, kAmbient);

    const double m = finM(p);
    const double L = p.length_m;
    const double error = maxError(
        model, [&](double x) { return thetaB * std::cosh(m * (L - x)) / std::cosh(m * L); });
    test::report("fin_fixed_base_200_cells_max_error_K", test::format(error));
    // Second-order finite volumes: the error is of order θ_b (m Δx)²/8 ≈ 3e-3 K
    // with m Δx = 0.023; 0.01 K (2e-4 of θ_b) leaves a factor three.
    EXPECT_LT(error, 0.01);

    // The heat through the base, from the ledger of the last (steady) step.
    const double before = model.energy().through_ends_J;
    StepConditions c;
    c.dt_s = 1000;
    model.step(c);
    const double baseHeat = -(model.energy().through_ends_J - before) / c.dt_s;
    const double exactHeat = p.conductivity_W_mK * p.area_m2() * m * thetaB * std::tanh(m * L);
    test::report("fin_fixed_base_heat_relative_error", test::format(baseHeat / exactHeat - 1));
    // Same second-order accuracy: 0.1 % is several times the discretisation error.
    EXPECT_NEAR(baseHeat, exactHeat, 1e-3 * exactHeat);
}

// A short fin (mL ≈ 1) fed by a heat flow Q at x = 0, insulated tip:
// θ(x) = Q cosh(m(L − x)) / (kA m sinh(mL)), so θ(0) = Q / (kA m tanh(mL)).
TEST(SteadyState, FinWithEndHeatFluxMatchesTanhLaw) {
    ScrewThermalParameters p = bareRod(0.2, 100);
    const double Q = 5;
    p.fixed_end = {Kind::HeatFlux, 0, Q};
    ScrewThermalModel model(p, kAmbient);
    test::stepToSteadyState(model, kAmbient);

    const double m = finM(p);
    const double L = p.length_m;
    const double kA = p.conductivity_W_mK * p.area_m2();
    const double theta0 = Q / (kA * m * std::tanh(m * L));
    const double error = maxError(
        model, [&](double x) { return Q * std::cosh(m * (L - x)) / (kA * m * std::sinh(m * L)); });
    // The face temperature from the first cell centre: Q crosses half a cell.
    const double dx = p.cellWidth_m();
    const double face = model.temperatures_C().front() - kAmbient + Q * 0.5 * dx / kA;
    test::report("fin_end_flux_theta0", test::format(face) + " K, rel. error " +
                                            test::format(face / theta0 - 1) +
                                            "; profile max error " + test::format(error) + " K");
    // mL = 1.03, m Δx = 0.01: discretisation error ~ θ (mΔx)² ≈ 1e-4 relative.
    EXPECT_NEAR(face, theta0, 1e-3 * theta0);
    EXPECT_LT(error, 1e-3 * theta0);
}

// A source at the insulated end of a long rod (mL ≈ 15) is, by mirror
// symmetry, half of a point source of 2Q in an infinite rod: θ(x) = Q e^{−mx}/(kAm),
// so the peak is Q/(kAm), twice the Q/(2kAm) of a source in mid-rod.
TEST(SteadyState, SourceAtInsulatedEndOfLongRodDecaysExponentially) {
    ScrewThermalParameters p = bareRod(3.0, 600);
    const double Q = 10;
    p.fixed_end = {Kind::HeatFlux, 0, Q};
    ScrewThermalModel model(p, kAmbient);
    test::stepToSteadyState(model, kAmbient);

    const double m = finM(p);
    const double kA = p.conductivity_W_mK * p.area_m2();
    ASSERT_GT(m * p.length_m, 15);  // coth(mL) − 1 < 1e-12: semi-infinite
    const double dx = p.cellWidth_m();
    const double peak = model.temperatures_C().front() - kAmbient + Q * 0.5 * dx / kA;
    const double exactPeak = Q / (kA * m);
    // Decay rate from two points 0.4 m apart: ln(θ(0.2)/θ(0.6)) / 0.4 = m.
    const double observedM = std::log((model.temperatureAt_C(0.2) - kAmbient) /
                                      (model.temperatureAt_C(0.6) - kAmbient)) /
                             0.4;
    test::report("long_rod_point_source", "peak " + test::format(peak) + " K, rel. error " +
                                              test::format(peak / exactPeak - 1) +
                                              "; decay rate rel. error " +
                                              test::format(observedM / m - 1));
    // Discrete decay rate m_h = m (1 − (mΔx)²/24 + …): 3e-5 relative with
    // m Δx = 0.026; linear interpolation between centres adds ~(mΔx)²/8 locally.
    EXPECT_NEAR(peak, exactPeak, 1e-3 * exactPeak);
    EXPECT_NEAR(observedM, m, 1e-3 * m);
    for (double x : {0.1, 0.3, 0.5, 0.8}) {
        const double exact = exactPeak * std::exp(-m * x);
        EXPECT_NEAR(model.temperatureAt_C(x) - kAmbient, exact, 2e-3 * exact) << "x = " << x;
    }
}

// The motor's heat entering evenly over the first L of a long rod with an
// insulated end: with q = Q/L per metre, θ = q/(hP) + B cosh(mx) on [0, L]
// and C e^{−m(x−L)} beyond; continuity of θ and θ' at L gives
// B = −q/(hP)·e^{−mL}, so θ(0) = q/(hP)(1 − e^{−mL}) and
// θ(x ≥ L) = q/(hP)·(1 − e^{−2mL})/2·e^{−m(x−L)} (as L → 0, the point source
// above).
TEST(SteadyState, MotorHeatEnteringOverALengthFollowsItsClosedForm) {
    ScrewThermalParameters p = bareRod(3.0, 600);
    const double Q = 10, L = 0.2;
    p.c_motor_W_per_Nm2 = Q;  // with a mean squared torque of 1 (N·m)²: Q watts
    p.motor_entry_m = L;
    ScrewThermalModel model(p, kAmbient);
    StepConditions c;
    c.dt_s = 1e9;
    c.ambient_begin_C = c.ambient_end_C = kAmbient;
    c.mean_torque_squared_Nm2 = 1;
    for (int i = 0; i < 6; ++i) model.step(c);
    EXPECT_NEAR(model.energy().motor_J, 6 * Q * c.dt_s, 1e-9 * 6 * Q * c.dt_s);

    const double m = finM(p);
    const double level = Q / L / (p.h_W_m2K * p.perimeter_m());
    const double atEnd = level * (1 - std::exp(-m * L));
    const double beyond = level * (1 - std::exp(-2 * m * L)) / 2;
    // The cell centre nearest the end lies half a cell in, where θ' ≈ 0.
    EXPECT_NEAR(model.temperatures_C().front() - kAmbient, atEnd, 2e-3 * atEnd);
    for (double x : {0.3, 0.5, 0.8}) {
        const double exact = beyond * std::exp(-m * (x - L));
        EXPECT_NEAR(model.temperatureAt_C(x) - kAmbient, exact, 2e-3 * exact) << "x = " << x;
    }
    // Entering within the end cell is the end cell's heat, as before.
    ScrewThermalParameters point = p;
    point.motor_entry_m = 0;
    ScrewThermalParameters withinACell = p;
    withinACell.motor_entry_m = 0.5 * p.cellWidth_m();
    ScrewThermalModel a(point, kAmbient), b(withinACell, kAmbient);
    a.step(c);
    b.step(c);
    EXPECT_EQ(a.temperatures_C(), b.temperatures_C());
}

// With insulated ends all heat leaves by convection, so at steady state
// h P ∫θ dx = Q whatever the source distribution: the free-end thermal error
// α∫θ dx = α Q / (h π d) must not depend on where the nut reciprocates.
TEST(SteadyState, FreeEndExpansionIsIndependentOfWhereTheNutRuns) {
    ScrewThermalParameters p;  // the machine screw, fixed end at axis −40 mm
    p.c_bearing_W_per_rad_s = 0;
    const double feed = 8000;  // mm/min
    const double omega = p.screwSpeed_rad_s(feed / 60e3);
    const double Q = p.nutPower_W(omega);
    const double exact_um = p.alpha_per_K * Q / (p.h_W_m2K * M_PI * p.diameter_m) * 1e6;  // ≈ 70 µm
    const double freeEnd_mm = p.fixed_end_axis_mm + p.length_m * 1e3;

    struct Range {
        double from_mm, to_mm;
    };
    double hottest[3] = {};
    int k = 0;
    for (Range r : {Range{100, 300}, Range{500, 700}, Range{20, 820}}) {
        std::vector<MotionSegment> motion;
        // 10 h = 12 time constants ρcd/(4h) ≈ 3000 s: the mean is within 1e-5.
        test::appendReciprocation(motion, r.from_mm, r.to_mm, feed, 0, 36000);
        ScrewThermalModel model(p, kAmbient);
        test::runFor(model, motion, 10, 36000, kAmbient);
        const double error_um = model.thermalError_um(freeEnd_mm);
        const auto& T = model.temperatures_C();
        hottest[k++] = *std::max_element(T.begin(), T.end()) - kAmbient;
        test::report("steady_expansion_" + std::to_string(int(r.from_mm)) + "_" +
                         std::to_string(int(r.to_mm)) + "_mm",
                     test::format(error_um) + " um, rel. error vs alpha Q/(h pi d) " +
                         test::format(error_um / exact_um - 1));
        // The nut heat per step is constant, so the mean temperature follows the
        // exact discrete relaxation; after 12 τ the residue is ~1e-5 relative.
        EXPECT_NEAR(error_um, exact_um, 1e-4 * exact_um)
            << "range " << r.from_mm << "–" << r.to_mm << " mm";
    }
    // The fields themselves differ a lot (a short stroke runs much hotter).
    EXPECT_GT(hottest[0], 1.5 * hottest[2]);
}

}  // namespace
}  // namespace driftlab::physics
