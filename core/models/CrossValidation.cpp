#include "core/models/CrossValidation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "core/models/LeastSquares.h"
#include "core/models/ModelError.h"

namespace driftlab::models {

std::vector<int> crossValidationFolds(const std::vector<RunData>& runs, int timeBlocks) {
    std::vector<int> folds;
    if (runs.size() > 1) {
        for (std::size_t r = 0; r < runs.size(); ++r)
            folds.insert(folds.end(), runs[r].observations.size(), int(r));
        return folds;
    }
    if (timeBlocks < 2)
        throw ModelError(QStringLiteral("cross-validating a single training run needs at least 2 "
                                        "time blocks, not %1")
                             .arg(timeBlocks));
    const std::vector<ErrorObservation>& obs = runs.front().observations;
    std::vector<std::size_t> byTime(obs.size());
    std::iota(byTime.begin(), byTime.end(), 0);
    std::stable_sort(byTime.begin(), byTime.end(),
                     [&](std::size_t a, std::size_t b) { return obs[a].time_s < obs[b].time_s; });
    folds.resize(obs.size());
    for (std::size_t rank = 0; rank < byTime.size(); ++rank)
        folds[byTime[rank]] = int(rank * std::size_t(timeBlocks) / byTime.size());
    return folds;
}

double crossValidatedRms(const Eigen::MatrixXd& X, const Eigen::VectorXd& y,
                         const std::vector<int>& folds) {
    const int foldCount = folds.empty() ? 0 : *std::max_element(folds.begin(), folds.end()) + 1;
    double heldOutSquares = 0;
    for (int f = 0; f < foldCount; ++f) {
        std::vector<Eigen::Index> train, test;
        for (std::size_t i = 0; i < folds.size(); ++i)
            (folds[i] == f ? test : train).push_back(Eigen::Index(i));
        if (test.empty()) continue;
        const Eigen::MatrixXd Xtrain = X(train, Eigen::all);
        if (Xtrain.rows() <= Xtrain.cols()) return std::numeric_limits<double>::infinity();
        const LeastSquaresFit fit = solveLeastSquares(Xtrain, y(train));
        if (!fit.full_rank) return std::numeric_limits<double>::infinity();
        heldOutSquares += (y(test) - X(test, Eigen::all) * fit.coefficients).squaredNorm();
    }
    return std::sqrt(heldOutSquares / double(folds.size()));
}

FoldNormalEquations::FoldNormalEquations(const Eigen::MatrixXd& X, const Eigen::VectorXd& y,
                                         const std::vector<int>& folds)
    : X_(X), y_(y), m_folds(folds) {
    const int foldCount = folds.empty() ? 0 : *std::max_element(folds.begin(), folds.end()) + 1;
    for (int f = 0; f < foldCount; ++f) {
        std::vector<Eigen::Index> rows;
        for (std::size_t i = 0; i < folds.size(); ++i)
            if (folds[i] == f) rows.push_back(Eigen::Index(i));
        m_heldOutX.push_back(X(rows, Eigen::all));
        m_heldOutY.push_back(y(rows));
        m_gram.push_back(m_heldOutX.back().transpose() * m_heldOutX.back());
        m_moment.push_back(m_heldOutX.back().transpose() * m_heldOutY.back());
    }
    m_totalGram = X.transpose() * X;
    m_totalMoment = X.transpose() * y;
}

double FoldNormalEquations::crossValidatedRms(const std::vector<Eigen::Index>& columns) const {
    // Beyond this condition number of the unit-diagonal normal matrix (10⁴ for
    // the design itself) the normal equations would lose digits a QR keeps.
    constexpr double kWellConditioned = 1e8;
    const auto k = Eigen::Index(columns.size());
    double heldOutSquares = 0;
    for (std::size_t f = 0; f < m_gram.size(); ++f) {
        const Eigen::Index heldOutRows = m_heldOutY[f].size();
        if (heldOutRows == 0) continue;
        if (Eigen::Index(m_folds.size()) - heldOutRows <= k)
            return std::numeric_limits<double>::infinity();
        const Eigen::MatrixXd G = m_totalGram(columns, columns) - m_gram[f](columns, columns);
        const Eigen::VectorXd b = m_totalMoment(columns) - m_moment[f](columns);
        // Unit diagonal, as solveLeastSquares scales its columns to unit norm.
        const Eigen::VectorXd scale = G.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
        const Eigen::MatrixXd unit = scale.asDiagonal() * G * scale.asDiagonal();
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(unit, Eigen::EigenvaluesOnly);
        const Eigen::VectorXd& lambda = eigen.eigenvalues();
        if (!(lambda.minCoeff() > lambda.maxCoeff() / kWellConditioned))
            return models::crossValidatedRms(X_(Eigen::all, columns), y_, m_folds);
        const Eigen::VectorXd beta = scale.asDiagonal() * unit.llt().solve(scale.asDiagonal() * b);
        // The residual itself, not yᵀy − 2βᵀXᵀy + βᵀXᵀXβ: that difference of
        // large numbers would bury a residual near the noise in rounding.
        heldOutSquares += (m_heldOutY[f] - m_heldOutX[f](Eigen::all, columns) * beta).squaredNorm();
    }
    return std::sqrt(heldOutSquares / double(m_folds.size()));
}

std::size_t simplestNearBest(const std::vector<double>& scores, double tolerance) {
    const auto best = std::min_element(scores.begin(), scores.end());
    if (best == scores.end() || !std::isfinite(*best)) return scores.size();
    const double acceptable = *best * (1 + tolerance) + 1e-6;
    for (std::size_t i = 0; i < scores.size(); ++i)
        if (scores[i] <= acceptable) return i;
    return scores.size();
}

}  // namespace driftlab::models
