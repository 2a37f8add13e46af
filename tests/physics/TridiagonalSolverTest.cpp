// The Thomas algorithm against Eigen's dense LU with partial pivoting.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "core/physics/TridiagonalSolver.h"

namespace driftlab::physics {
namespace {

TEST(TridiagonalSolver, MatchesDenseLuOnDiagonallyDominantSystems) {
    std::mt19937 rng(230);
    std::uniform_real_distribution<double> off(-1.0, 1.0);
    for (int n : {3, 4, 17, 200}) {
        std::vector<double> lower(n), diag(n), upper(n), rhs(n);
        Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
        Eigen::VectorXd b(n);
        for (int i = 0; i < n; ++i) {
            const auto k = static_cast<std::size_t>(i);
            lower[k] = i > 0 ? off(rng) : 0.0;
            upper[k] = i + 1 < n ? off(rng) : 0.0;
            // Strict dominance with a random margin, as conduction gives.
            diag[k] = std::abs(lower[k]) + std::abs(upper[k]) + 0.1 + std::abs(off(rng));
            if (i % 2) diag[k] = -diag[k];  // sign does not matter to dominance
            rhs[k] = 10 * off(rng);
            A(i, i) = diag[k];
            if (i > 0) A(i, i - 1) = lower[k];
            if (i + 1 < n) A(i, i + 1) = upper[k];
            b(i) = rhs[k];
        }
        const Eigen::VectorXd x = A.partialPivLu().solve(b);
        TridiagonalSolver solver;
        solver.factorise(lower, diag, upper);
        ASSERT_EQ(solver.size(), static_cast<std::size_t>(n));
        solver.solve(rhs.data());
        // Both are backward stable on a well-conditioned (dominant) matrix:
        // agreement to ~1e-15·cond, asserted at 1e-12 of the solution size.
        const double scale = x.cwiseAbs().maxCoeff();
        for (int i = 0; i < n; ++i)
            EXPECT_NEAR(rhs[static_cast<std::size_t>(i)], x(i), 1e-12 * scale)
                << "n " << n << " i " << i;

        // The factorisation is reusable: a second right-hand side, same matrix.
        Eigen::VectorXd b2 = Eigen::VectorXd::LinSpaced(n, -1, 1);
        std::vector<double> rhs2(b2.data(), b2.data() + n);
        solver.solve(rhs2.data());
        const Eigen::VectorXd x2 = A.partialPivLu().solve(b2);
        for (int i = 0; i < n; ++i)
            EXPECT_NEAR(rhs2[static_cast<std::size_t>(i)], x2(i), 1e-12 * x2.cwiseAbs().maxCoeff());
    }
}

}  // namespace
}  // namespace driftlab::physics
