#include "core/models/CrossValidation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

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

std::size_t simplestNearBest(const std::vector<double>& scores, double tolerance) {
    const auto best = std::min_element(scores.begin(), scores.end());
    if (best == scores.end() || !std::isfinite(*best)) return scores.size();
    const double acceptable = *best * (1 + tolerance) + 1e-6;
    for (std::size_t i = 0; i < scores.size(); ++i)
        if (scores[i] <= acceptable) return i;
    return scores.size();
}

}  // namespace driftlab::models
