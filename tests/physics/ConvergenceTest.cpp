// Observed orders of convergence: in time (backward Euler 1, Crank–Nicolson 2)
// and in space (2, cell-centred finite volumes), printed with the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/physics/ScrewThermalModel.h"
#include "tests/physics/PhysicsTestSupport.h"

namespace driftlab::physics {
namespace {

using test::bareRod;
using Kind = EndCondition::Kind;

// A transient with smooth data: the rod starts at 20 °C with its base held at
// 20 °C while the ambient rises at 6 K/h, so heat flows in by convection and
// out through the base. (A sudden base step would excite the stiffest modes,
// which Crank–Nicolson does not damp, and blur its order at coarse steps.)
double temperatureAfter600s(double theta, double dt_s) {
    ScrewThermalParameters p = bareRod(0.9, 100);
    p.theta = theta;
    p.fixed_end = {Kind::FixedTemperature, 20, 0};
    ScrewThermalModel model(p, 20);
    const double rate = 6.0 / 3600;  // K/s
    StepConditions c;
    c.dt_s = dt_s;
    const auto steps = std::lround(600 / dt_s);
    for (long i = 0; i < steps; ++i) {
        c.ambient_begin_C = 20 + rate * model.time_s();
        c.ambient_end_C = 20 + rate * (model.time_s() + dt_s);
        model.step(c);
    }
    return model.temperatureAt_C(0.05);  // near the base, where the profile bends
}

// The reference is the same grid with Crank–Nicolson at Δt = 0.02 s: its time
// error (~1e-10 K) is far below the smallest error measured, and the spatial
// error cancels because every run shares the grid.
TEST(Convergence, TimeStepOrderIsOneForBackwardEulerAndTwoForCrankNicolson) {
    const double reference = temperatureAfter600s(0.5, 0.02);
    const std::vector<double> steps{40, 20, 10, 5};
    for (double theta : {1.0, 0.5}) {
        std::vector<double> errors;
        for (double dt : steps)
            errors.push_back(std::abs(temperatureAfter600s(theta, dt) - reference));
        std::string text;
        for (std::size_t i = 0; i < steps.size(); ++i) {
            text += "dt " + test::format(steps[i]) + " s: " + test::format(errors[i]) + " K";
            if (i > 0)
                text +=
                    " (order " + test::format(test::observedOrder(errors[i - 1], errors[i])) + ")";
            text += i + 1 < steps.size() ? "; " : "";
        }
        test::report(theta == 1 ? "time_order_BE" : "time_order_CN", text);
        for (std::size_t i = 1; i < steps.size(); ++i) {
            const double order = test::observedOrder(errors[i - 1], errors[i]);
            // The asymptotic orders are 1 and 2; a ±0.2/0.3 band absorbs the
            // next term of the error expansion at the coarsest steps.
            if (theta == 1) {
                EXPECT_GT(order, 0.8) << "dt " << steps[i];
                EXPECT_LT(order, 1.2) << "dt " << steps[i];
            } else {
                EXPECT_GT(order, 1.7) << "dt " << steps[i];
                EXPECT_LT(order, 2.3) << "dt " << steps[i];
            }
        }
    }
}

// Grid refinement against the analytic steady fin θ_b cosh(m(L − x))/cosh(mL)
// (base held at 70 °C, insulated tip): the max error over cell centres must
// fall about fourfold per halving of Δx.
TEST(Convergence, GridOrderIsTwoAgainstAnalyticFin) {
    const std::vector<int> grids{25, 50, 100, 200, 400};
    std::vector<double> errors;
    for (int cells : grids) {
        ScrewThermalParameters p = bareRod(0.9, cells);
        p.fixed_end = {Kind::FixedTemperature, 70, 0};
        ScrewThermalModel model(p, 20);
        test::stepToSteadyState(model, 20);
        const double m = test::finM(p), L = p.length_m;
        double worst = 0;
        for (int i = 0; i < cells; ++i) {
            const double exact = 50 * std::cosh(m * (L - model.cellCentre_m(i))) / std::cosh(m * L);
            worst = std::max(
                worst, std::abs(model.temperatures_C()[static_cast<std::size_t>(i)] - 20 - exact));
        }
        errors.push_back(worst);
    }
    std::string text;
    for (std::size_t i = 0; i < grids.size(); ++i) {
        text += std::to_string(grids[i]) + " cells: " + test::format(errors[i]) + " K";
        if (i > 0)
            text += " (order " + test::format(test::observedOrder(errors[i - 1], errors[i])) + ")";
        text += i + 1 < grids.size() ? "; " : "";
    }
    test::report("grid_order_fin", text);
    for (std::size_t i = 1; i < grids.size(); ++i) {
        const double order = test::observedOrder(errors[i - 1], errors[i]);
        // Second order, ±0.2 for the higher terms on the coarsest grid (mΔx = 0.19).
        EXPECT_GT(order, 1.8) << grids[i] << " cells";
        EXPECT_LT(order, 2.2) << grids[i] << " cells";
    }
}

}  // namespace
}  // namespace driftlab::physics
