#include "core/models/NelderMead.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace driftlab::models {

NelderMeadResult minimiseNelderMead(const std::function<double(const Eigen::VectorXd&)>& f,
                                    const Eigen::VectorXd& x0, const NelderMeadOptions& options) {
    const Eigen::Index n = x0.size();
    std::vector<Eigen::VectorXd> simplex{x0};
    for (Eigen::Index i = 0; i < n; ++i) {
        Eigen::VectorXd v = x0;
        v[i] += options.initial_step;
        simplex.push_back(v);
    }
    std::vector<double> values;
    for (const Eigen::VectorXd& v : simplex) values.push_back(f(v));
    std::vector<std::size_t> order(simplex.size());

    NelderMeadResult result;
    for (; result.iterations < options.max_iterations; ++result.iterations) {
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
        const std::size_t best = order.front(), worst = order.back(),
                          secondWorst = order[order.size() - 2];
        double size = 0;
        for (const Eigen::VectorXd& v : simplex)
            size = std::max(size, (v - simplex[best]).cwiseAbs().maxCoeff());
        if (size < options.x_tolerance) {
            result.converged = true;
            break;
        }
        Eigen::VectorXd centroid = Eigen::VectorXd::Zero(n);
        for (std::size_t i : order)
            if (i != worst) centroid += simplex[i] / double(n);
        auto along = [&](double t) -> Eigen::VectorXd {
            return centroid + t * (simplex[worst] - centroid);
        };
        auto replaceWorst = [&](const Eigen::VectorXd& v, double fv) {
            simplex[worst] = v;
            values[worst] = fv;
        };

        const Eigen::VectorXd reflected = along(-1);
        const double fr = f(reflected);
        if (fr < values[best]) {
            const Eigen::VectorXd expanded = along(-2);
            const double fe = f(expanded);
            fe < fr ? replaceWorst(expanded, fe) : replaceWorst(reflected, fr);
            continue;
        }
        if (fr < values[secondWorst]) {
            replaceWorst(reflected, fr);
            continue;
        }
        const Eigen::VectorXd contracted = fr < values[worst] ? along(-0.5) : along(0.5);
        const double fc = f(contracted);
        if (fc < std::min(fr, values[worst])) {
            replaceWorst(contracted, fc);
            continue;
        }
        for (std::size_t i = 0; i < simplex.size(); ++i) {
            if (i == best) continue;
            simplex[i] = simplex[best] + 0.5 * (simplex[i] - simplex[best]);
            values[i] = f(simplex[i]);
        }
    }
    const auto best = std::min_element(values.begin(), values.end()) - values.begin();
    result.x = simplex[std::size_t(best)];
    result.value = values[std::size_t(best)];
    return result;
}

}  // namespace driftlab::models
