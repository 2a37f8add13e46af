// Transients against analytic solutions: lumped Newton cooling, a
// semi-infinite rod under constant end flux, and a fast-reciprocating nut
// against the steady field of the same heat smeared over its range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/physics/ScrewThermalModel.h"
#include "tests/physics/PhysicsTestSupport.h"

namespace driftlab::physics {
namespace {

using test::bareRod;
using Kind = EndCondition::Kind;

// A rod at a uniform temperature with insulated ends stays uniform (no
// conduction) and cools as one lump: ρcA dT/dt = −hP (T − Ta), so
// T − Ta = ΔT0 exp(−t/τ), τ = ρ c d / (4h) ≈ 3009 s. The lump is physical:
// the Biot number h(d/2)/k = 0.005 is far below 0.1.
TEST(Transient, UniformRodCoolsWithLumpedTimeConstant) {
    for (double theta : {1.0, 0.5}) {
        ScrewThermalParameters p = bareRod(0.9, 50);
        p.theta = theta;
        const double tau = p.density_kg_m3 * p.specific_heat_J_kgK * p.diameter_m / (4 * p.h_W_m2K);
        const double dT0 = 50;
        ScrewThermalModel model(p, 20 + dT0);
        StepConditions c;
        c.dt_s = 5;
        c.ambient_begin_C = c.ambient_end_C = 20;
        double worst = 0;
        for (int step = 1; step <= 1800; ++step) {  // 3 τ
            model.step(c);
            if (step % 300 != 0) continue;
            const double exact = std::exp(-model.time_s() / tau);
            const double got = (model.temperatureAt_C(0.45) - 20) / dT0;
            worst = std::max(worst, std::abs(got / exact - 1));
            // Backward Euler's relative error is t·Δt/(2τ²) ≤ 2.5e-3 at 3τ with
            // Δt = 5 s; Crank–Nicolson's is ~t·Δt²/(12τ³) ≈ 1e-6. Both < 0.5 %.
            EXPECT_NEAR(got, exact, 5e-3 * exact) << "t = " << model.time_s() << " s";
        }
        test::report(theta == 1 ? "lumped_cooling_BE_rel_error" : "lumped_cooling_CN_rel_error",
                     test::format(worst));
    }
}

// Constant heat flux q'' = Q/A into the end of a semi-infinite rod without
// convection (Carslaw & Jaeger 2.9):
//   θ(x,t) = (2q''/k) [ sqrt(αt/π) exp(−x²/(4αt)) − (x/2) erfc(x / (2 sqrt(αt))) ],
// so the surface temperature is 2 q'' sqrt(αt/π) / k.
TEST(Transient, SemiInfiniteRodUnderConstantFluxFollowsErfcSolution) {
    ScrewThermalParameters p = bareRod(0.5, 1000);
    p.h_W_m2K = 0;
    const double Q = 20;
    p.fixed_end = {Kind::HeatFlux, 0, Q};
    ScrewThermalModel model(p, 20);
    const double k = p.conductivity_W_mK;
    const double q = Q / p.area_m2();
    const double alpha = test::diffusivity(p);
    // At 600 s the penetration depth sqrt(αt) = 0.087 m: the 0.5 m rod's far
    // end sees erfc(2.9) ≈ 4e-5 of the surface rise, semi-infinite enough.
    auto exact = [&](double x, double t) {
        const double s = std::sqrt(alpha * t);
        return 2 * q / k *
               (s / std::sqrt(M_PI) * std::exp(-x * x / (4 * s * s)) -
                0.5 * x * std::erfc(x / (2 * s)));
    };
    StepConditions c;
    c.dt_s = 0.1;
    const double dx = p.cellWidth_m();
    for (double checkAt : {60.0, 600.0}) {
        while (model.time_s() < checkAt - 1e-9) model.step(c);
        const double t = model.time_s();
        const double surfaceExact = exact(0, t);
        // Face temperature: the flux crosses the half cell next to the end.
        const double surface = model.temperatures_C().front() - 20 + q * 0.5 * dx / k;
        double worst = 0;
        for (int i = 0; i < 400; i += 10)
            worst = std::max(worst, std::abs(model.temperatures_C()[static_cast<std::size_t>(i)] -
                                             20 - exact(model.cellCentre_m(i), t)));
        test::report("semi_infinite_flux_t" + std::to_string(int(checkAt)),
                     "surface " + test::format(surface) + " K, rel. error " +
                         test::format(surface / surfaceExact - 1) + "; profile max error " +
                         test::format(worst) + " K");
        // Δx = 0.5 mm and Δt = 0.1 s resolve the sqrt(t) start: the error is
        // dominated by backward Euler's first steps, well under 1 %.
        EXPECT_NEAR(surface, surfaceExact, 0.01 * surfaceExact) << "t = " << t;
        EXPECT_LT(worst, 0.01 * surfaceExact) << "t = " << t;
    }
}

// A nut reciprocating fast over [a, b] heats like its time average: power
// density q(ξ) = Q |[ξ − w/2, ξ + w/2] ∩ [a, b]| / (w (b − a)). On a rod with
// insulated ends the steady field is θ(x) = ∫ G(x, ξ) q(ξ) dξ with the Green's
// function G = cosh(m x<) cosh(m (L − x>)) / (kA m sinh(mL)), integrated here
// numerically. The exact deposition must give it whatever the step, even a
// step spanning twenty strokes (no aliasing of the coarse step).
TEST(Transient, FastReciprocationConvergesToSmearedSourceForAnyStep) {
    ScrewThermalParameters p = bareRod(0.9, 200);
    const double a = 0.2, b = 0.4, w = p.nut_length_m, feed = 8000;  // 1.5 s strokes
    p.c_nut_W_per_rad_s = 0.11;
    const double Q = p.nutPower_W(p.screwSpeed_rad_s(feed / 60e3));  // 9.2 W
    const double m = test::finM(p), L = p.length_m;
    const double kA = p.conductivity_W_mK * p.area_m2();

    auto source = [&](double xi) {
        const double overlap = std::max(0.0, std::min(xi + w / 2, b) - std::max(xi - w / 2, a));
        return Q * overlap / (w * (b - a));
    };
    auto smeared = [&](double x) {
        // Midpoint rule on 40 000 points over the support: the integrand has
        // only kinks, so the quadrature error is below 1e-8 relative.
        const double lo = a - w / 2, hi = b + w / 2;
        const int n = 40000;
        const double h = (hi - lo) / n;
        double sum = 0;
        for (int j = 0; j < n; ++j) {
            const double xi = lo + (j + 0.5) * h;
            const double s = std::min(x, xi), g = std::max(x, xi);
            sum += std::cosh(m * s) * std::cosh(m * (L - g)) * source(xi);
        }
        return sum * h / (kA * m * std::sinh(m * L));
    };

    std::vector<MotionSegment> motion;
    const double duration = 30000;  // 10 τ: transients below 5e-5
    test::appendReciprocation(motion, a * 1e3, b * 1e3, feed, 0, duration);
    std::vector<double> reference;
    for (int i = 0; i < 200; i += 5) reference.push_back(smeared((i + 0.5) * p.cellWidth_m()));
    const double peak = *std::max_element(reference.begin(), reference.end());

    std::vector<std::vector<double>> fields;
    for (double dt : {1.0, 5.0, 30.0}) {
        ScrewThermalModel model(p, 20);
        test::runFor(model, motion, dt, duration, 20);
        double worst = 0;
        for (std::size_t j = 0; j < reference.size(); ++j)
            worst = std::max(worst, std::abs(model.temperatures_C()[5 * j] - 20 - reference[j]));
        test::report(
            "smeared_nut_dt" + std::to_string(int(dt)),
            "max error " + test::format(worst) + " K of peak " + test::format(peak) + " K");
        // Spatial discretisation ~(mΔx)²/8 = 7e-5 of the peak (m Δx = 0.023);
        // the ripple of a 9 W nut passing every 1.5 s is smaller. 1e-3 of the
        // peak leaves a margin of ten; a nut deposited where the step ends
        // (aliased) would be off by kelvins at Δt = 30 s.
        EXPECT_LT(worst, 1e-3 * peak) << "dt = " << dt << " s";
        fields.push_back(model.temperatures_C());
    }
    double spread = 0;
    for (std::size_t i = 0; i < fields[0].size(); ++i)
        spread = std::max(
            {spread, std::abs(fields[1][i] - fields[0][i]), std::abs(fields[2][i] - fields[0][i])});
    test::report("smeared_nut_step_spread", test::format(spread) + " K");
    // Backward Euler's steady state does not depend on the step, and the
    // deposited energy per cell is exact: only the ripple differs (2e-5 of
    // the peak observed), bounded at 5e-4.
    EXPECT_LT(spread, 5e-4 * peak);
}

}  // namespace
}  // namespace driftlab::physics
