#include "core/models/LeastSquares.h"

#include <Eigen/QR>
#include <cmath>
#include <limits>

namespace driftlab::models {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// Relative size of a pivot below which a (unit-norm) column counts as dependent.
constexpr double kRankThreshold = 1e-10;

Eigen::VectorXd columnScales(const Eigen::MatrixXd& X) {
    Eigen::VectorXd s = X.colwise().norm().transpose();
    for (Eigen::Index j = 0; j < s.size(); ++j)
        if (!(s[j] > 0)) s[j] = 1;
    return s;
}

struct ScaledQr {
    Eigen::VectorXd scale;
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
    explicit ScaledQr(const Eigen::MatrixXd& X)
        : scale(columnScales(X)), qr(X * scale.cwiseInverse().asDiagonal()) {
        qr.setThreshold(kRankThreshold);
    }
    bool fullRank() const { return qr.rank() == qr.cols(); }
    /// sqrt(diag((XᵀX)⁻¹)) in the unscaled parameters; requires full rank.
    Eigen::VectorXd inverseNormalDiagonalSqrt() const {
        const Eigen::Index p = qr.cols();
        const Eigen::MatrixXd R = qr.matrixR().topLeftCorner(p, p).triangularView<Eigen::Upper>();
        const Eigen::MatrixXd Rinv =
            R.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(p, p));
        const Eigen::MatrixXd inverse =
            qr.colsPermutation() * (Rinv * Rinv.transpose()) * qr.colsPermutation().transpose();
        return inverse.diagonal().cwiseSqrt().cwiseQuotient(scale);
    }
};

}  // namespace

LeastSquaresFit solveLeastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y) {
    const ScaledQr scaled(X);
    LeastSquaresFit fit;
    fit.full_rank = scaled.fullRank();
    fit.coefficients = scaled.qr.solve(y).cwiseQuotient(scaled.scale);
    fit.rss = (y - X * fit.coefficients).squaredNorm();
    const Eigen::Index dof = X.rows() - X.cols();
    if (fit.full_rank && dof > 0)
        fit.sigma = std::sqrt(fit.rss / double(dof)) * scaled.inverseNormalDiagonalSqrt();
    else
        fit.sigma = Eigen::VectorXd::Constant(X.cols(), kNaN);
    return fit;
}

Eigen::VectorXd parameterSigma(const Eigen::MatrixXd& J, double rss) {
    const ScaledQr scaled(J);
    const Eigen::Index dof = J.rows() - J.cols();
    if (!scaled.fullRank() || dof <= 0) return Eigen::VectorXd::Constant(J.cols(), kNaN);
    return std::sqrt(rss / double(dof)) * scaled.inverseNormalDiagonalSqrt();
}

Eigen::MatrixXd withPositionGain(const Eigen::MatrixXd& F, const Eigen::VectorXd& dx) {
    Eigen::MatrixXd X(F.rows(), 2 * F.cols());
    X << F, dx.asDiagonal() * F;
    return X;
}

double rSquared(double rss, const Eigen::VectorXd& y) {
    const double tss = (y.array() - y.mean()).square().sum();
    return tss > 0 ? 1 - rss / tss : kNaN;
}

}  // namespace driftlab::models
