#pragma once
// Thomas algorithm for the screw's tridiagonal system, split into factorise
// and solve. The conduction matrix only changes when the step or the
// convection coefficient changes, so the simulation factorises once and each
// step costs two sweeps of multiply-adds (no division). A general sparse
// solver (Eigen's SparseLU) would redo symbolic work per step and is an order
// of magnitude slower on 200 unknowns; the 30 lines below are the classic
// algorithm, checked against a dense Eigen solve in the tests.

#include <cstddef>
#include <vector>

namespace driftlab::physics {

class TridiagonalSolver {
public:
    /// Factorises the matrix with sub-diagonal `lower` (lower[0] unused),
    /// diagonal `diag` and super-diagonal `upper` (upper[n-1] unused).
    /// The matrix must be diagonally dominant (it is, for conduction).
    void factorise(const std::vector<double>& lower, const std::vector<double>& diag,
                   const std::vector<double>& upper) {
        const std::size_t n = diag.size();
        lower_ = lower;
        upperPrime_.resize(n);
        inverseDiag_.resize(n);
        inverseDiag_[0] = 1.0 / diag[0];
        upperPrime_[0] = upper[0] * inverseDiag_[0];
        for (std::size_t i = 1; i < n; ++i) {
            inverseDiag_[i] = 1.0 / (diag[i] - lower[i] * upperPrime_[i - 1]);
            upperPrime_[i] = i + 1 < n ? upper[i] * inverseDiag_[i] : 0.0;
        }
    }

    /// Solves in place: `rhs` becomes the solution.
    void solve(double* rhs) const {
        const std::size_t n = inverseDiag_.size();
        rhs[0] *= inverseDiag_[0];
        for (std::size_t i = 1; i < n; ++i)
            rhs[i] = (rhs[i] - lower_[i] * rhs[i - 1]) * inverseDiag_[i];
        for (std::size_t i = n - 1; i-- > 0;) rhs[i] -= upperPrime_[i] * rhs[i + 1];
    }

    std::size_t size() const { return inverseDiag_.size(); }

private:
    std::vector<double> lower_;
    std::vector<double> upperPrime_;
    std::vector<double> inverseDiag_;
};

}  // namespace driftlab::physics
