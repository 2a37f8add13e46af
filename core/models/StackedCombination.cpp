#include "core/models/StackedCombination.h"

#include <Eigen/Dense>
#include <algorithm>
#include <limits>

#include "core/models/CrossValidation.h"

namespace driftlab::models {
namespace {

/// The weights on `in` minimising wᵀGw − 2cᵀw with Σw = 1 and no sign
/// constraint, from the equality-constrained system
/// [G_SS 1; 1ᵀ 0]·[w; ν] = [c_S; 1]; zero outside `in`.
Eigen::VectorXd onTheSet(const Eigen::MatrixXd& G, const Eigen::VectorXd& c,
                         const std::vector<bool>& in) {
    std::vector<Eigen::Index> set;
    for (std::size_t i = 0; i < in.size(); ++i)
        if (in[i]) set.push_back(Eigen::Index(i));
    const auto m = Eigen::Index(set.size());
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(m + 1, m + 1);
    K.topLeftCorner(m, m) = G(set, set);
    K.topRightCorner(m, 1).setOnes();
    K.bottomLeftCorner(1, m).setOnes();
    Eigen::VectorXd rhs(m + 1);
    rhs << c(set), 1.0;
    const Eigen::VectorXd solution = K.completeOrthogonalDecomposition().solve(rhs);
    Eigen::VectorXd w = Eigen::VectorXd::Zero(G.rows());
    for (Eigen::Index i = 0; i < m; ++i) w[set[std::size_t(i)]] = solution[i];
    return w;
}

}  // namespace

Eigen::VectorXd stackingWeights(const Eigen::MatrixXd& P, const Eigen::VectorXd& y) {
    const Eigen::Index F = P.cols();
    const double rows = std::max<double>(1, double(P.rows()));
    // The squared error over the readings is wᵀGw − 2cᵀw + yᵀy/rows.
    const Eigen::MatrixXd G = P.transpose() * P / rows;
    const Eigen::VectorXd c = P.transpose() * y / rows;
    // A column joins when it lowers the error by more than rounding of G.
    const double tolerance =
        1e-10 * std::max(G.diagonal().cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());

    // Start at the best single column (a vertex of the simplex).
    Eigen::Index first = 0;
    (G.diagonal() - 2 * c).minCoeff(&first);
    std::vector<bool> in(std::size_t(F), false);
    in[std::size_t(first)] = true;
    Eigen::VectorXd w = Eigen::VectorXd::Zero(F);
    w[first] = 1;

    for (int outer = 0; outer < 4 * int(F) + 4; ++outer) {
        // Optimal on the simplex when no column outside the set has a lower
        // gradient than the set's common one (μ = wᵀg, their weighted mean).
        const Eigen::VectorXd g = G * w - c;
        const double mu = w.dot(g);
        Eigen::Index join = -1;
        double steepest = -tolerance;
        for (Eigen::Index j = 0; j < F; ++j)
            if (!in[std::size_t(j)] && g[j] - mu < steepest) {
                steepest = g[j] - mu;
                join = j;
            }
        if (join < 0) break;
        in[std::size_t(join)] = true;
        // Move towards the set's unconstrained optimum, dropping the columns
        // whose weight reaches zero on the way, until it is inside.
        for (int inner = 0; inner <= int(F); ++inner) {
            const Eigen::VectorXd z = onTheSet(G, c, in);
            double step = 1;
            Eigen::Index blocking = -1;
            for (Eigen::Index i = 0; i < F; ++i)
                if (in[std::size_t(i)] && z[i] <= 0) {
                    const double s = w[i] / (w[i] - z[i]);
                    if (s < step) {
                        step = s;
                        blocking = i;
                    }
                }
            w += step * (z - w);
            if (blocking < 0) break;
            for (Eigen::Index i = 0; i < F; ++i)
                if (in[std::size_t(i)] && (i == blocking || w[i] <= 0)) {
                    in[std::size_t(i)] = false;
                    w[i] = 0;
                }
        }
    }
    w = w.cwiseMax(0.0);
    return w / w.sum();
}

HeldOutPredictions weightedPredictions(const std::vector<HeldOutPredictions>& families,
                                       const std::vector<double>& weights) {
    HeldOutPredictions combined = families.front();
    for (std::size_t i = 0; i < combined.predicted_um.size(); ++i) {
        double sum = 0;
        for (std::size_t f = 0; f < families.size(); ++f)
            sum += weights[f] * families[f].predicted_um[i];
        combined.predicted_um[i] = sum;
    }
    return combined;
}

std::vector<std::size_t> nearBestFamilies(const std::vector<HeldOutPredictions>& families,
                                          const std::vector<bool>& inMean) {
    std::vector<std::size_t> candidates;
    for (std::size_t f = 0; f < families.size(); ++f)
        if (inMean[f]) candidates.push_back(f);
    if (candidates.empty()) return {};
    const auto bestAt = *std::min_element(
        candidates.begin(), candidates.end(),
        [&](std::size_t a, std::size_t b) { return families[a].rms_um() < families[b].rms_um(); });
    const double best = families[bestAt].rms_um();
    const double se = families[bestAt].standard_error_um();
    const double window = best * (1 + std::max(0.02, best > 0 ? se / best : 0));
    std::vector<std::size_t> members;
    for (std::size_t f : candidates)
        if (families[f].rms_um() <= window) members.push_back(f);
    std::stable_sort(members.begin(), members.end(), [&](std::size_t a, std::size_t b) {
        return families[a].rms_um() < families[b].rms_um();
    });
    return members;
}

CombinationChoice chooseCombination(const std::vector<HeldOutPredictions>& families,
                                    const std::vector<bool>& inMean) {
    using Kind = CombinationChoice::Kind;
    CombinationChoice choice;
    const HeldOutPredictions& reference = families.front();
    const auto rows = Eigen::Index(reference.measured_um.size());
    const auto F = Eigen::Index(families.size());
    Eigen::MatrixXd P(rows, F);
    for (Eigen::Index f = 0; f < F; ++f)
        P.col(f) =
            Eigen::Map<const Eigen::VectorXd>(families[std::size_t(f)].predicted_um.data(), rows);
    const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(reference.measured_um.data(), rows);
    const Eigen::VectorXd w = stackingWeights(P, y);
    const double none = reference.none_rms_um();

    // The stack, heaviest first.
    std::vector<std::size_t> stacked;
    for (Eigen::Index f = 0; f < F; ++f)
        if (w[f] > 0) stacked.push_back(std::size_t(f));
    std::stable_sort(stacked.begin(), stacked.end(), [&](std::size_t a, std::size_t b) {
        return w[Eigen::Index(a)] > w[Eigen::Index(b)];
    });
    choice.stack_weights.assign(w.data(), w.data() + w.size());
    auto combination = [&](const std::vector<std::size_t>& members,
                           const std::vector<double>& weights) {
        std::vector<HeldOutPredictions> parts;
        for (std::size_t f : members) parts.push_back(families[f]);
        return weightedPredictions(parts, weights);
    };
    std::vector<double> stackedWeights;
    for (std::size_t f : stacked) stackedWeights.push_back(w[Eigen::Index(f)]);
    const HeldOutPredictions stack = combination(stacked, stackedWeights);
    choice.stack_rms_um = stack.rms_um();

    // The equal-weight mean of the near-best families.
    const std::vector<std::size_t> near = nearBestFamilies(families, inMean);
    const std::vector<double> equal(near.size(), near.empty() ? 0.0 : 1.0 / double(near.size()));
    HeldOutPredictions mean;
    choice.mean_rms_um = std::numeric_limits<double>::infinity();
    if (!near.empty()) {
        mean = combination(near, equal);
        choice.mean_rms_um = mean.rms_um();
    }

    // The stack must earn its place against the mean, as a further input
    // must in every family: a cross-validated RMS lower by 2 %.
    if (simplestNearBest({choice.mean_rms_um, choice.stack_rms_um}) == 0) {
        choice.kind = Kind::Mean;
        choice.members = near;
        choice.weights = equal;
        choice.predictions = std::move(mean);
    } else {
        choice.kind = Kind::Stacked;
        choice.members = stacked;
        choice.weights = stackedWeights;
        choice.predictions = stack;
    }
    if (choice.predictions.rms_um() < none) return choice;

    // No harm: the best family alone where it does better than none, else
    // nothing.
    std::size_t best = 0;
    for (std::size_t f = 1; f < families.size(); ++f)
        if (families[f].rms_um() < families[best].rms_um()) best = f;
    if (families[best].rms_um() < none) {
        choice.kind = Kind::BestSingle;
        choice.members = {best};
        choice.weights = {1.0};
        choice.predictions = families[best];
        return choice;
    }
    choice.kind = Kind::None;
    choice.members.clear();
    choice.weights.clear();
    choice.predictions = reference;
    std::fill(choice.predictions.predicted_um.begin(), choice.predictions.predicted_um.end(), 0.0);
    return choice;
}

}  // namespace driftlab::models
