#include "core/models/FirstOrderLag.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace driftlab::models {

Eigen::VectorXd lagResponse(const PiecewiseInput& input, double tau_s,
                            const std::vector<double>& at_s) {
    std::vector<std::size_t> order(at_s.size());
    std::iota(order.begin(), order.end(), 0);
    if (!std::is_sorted(at_s.begin(), at_s.end()))
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return at_s[a] < at_s[b]; });
    // Logged at a fixed interval, the steps repeat one Δt: its decay factor is
    // computed once (the exponential dominates the cost of a fit's search).
    double lastDt = -1, lastFactor = 0;
    auto step = [&](double e, double u, double dt) {
        if (dt == 0) return e;
        if (dt != lastDt) {
            lastDt = dt;
            lastFactor = -std::expm1(-dt / tau_s);
        }
        return e + (u - e) * lastFactor;
    };

    Eigen::VectorXd response = Eigen::VectorXd::Zero(Eigen::Index(at_s.size()));
    const std::vector<double>& t = input.time_s;
    if (t.empty()) return response;
    double state = 0;   // e at time t[k]
    std::size_t k = 0;  // the input piece in force
    for (std::size_t i : order) {
        const double when = at_s[i];
        if (when < t.front()) continue;
        while (k + 1 < t.size() && t[k + 1] <= when) {
            state = step(state, input.value[k], t[k + 1] - t[k]);
            ++k;
        }
        response[Eigen::Index(i)] = step(state, input.value[k], when - t[k]);
    }
    return response;
}

}  // namespace driftlab::models
