#include "core/diagnosis/LateSensor.h"

#include <algorithm>

namespace driftlab::diagnosis {

std::vector<double> beforeTheLag(const std::vector<double>& time_s,
                                 const std::vector<double>& value, double tau_s,
                                 double halfWindow_s) {
    const std::size_t n = std::min(time_s.size(), value.size());
    if (n < 3 || !(tau_s > 0)) return value;
    // Prefix sums of t, y, t·y and t² (t from the first reading, to keep the
    // sums small): a least-squares line per window in O(1).
    const double t0 = time_s.front();
    std::vector<double> st(n + 1, 0), sy(n + 1, 0), sty(n + 1, 0), stt(n + 1, 0);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = time_s[k] - t0;
        st[k + 1] = st[k] + t;
        sy[k + 1] = sy[k] + value[k];
        sty[k + 1] = sty[k] + t * value[k];
        stt[k + 1] = stt[k] + t * t;
    }
    std::vector<double> seen(value.begin(), value.begin() + std::ptrdiff_t(n));
    std::size_t a = 0, b = 0;  // the window [a, b)
    for (std::size_t k = 0; k < n; ++k) {
        while (time_s[a] < time_s[k] - halfWindow_s) ++a;
        while (b < n && time_s[b] <= time_s[k] + halfWindow_s) ++b;
        const double m = double(b - a);
        const double sumT = st[b] - st[a], sumY = sy[b] - sy[a];
        const double sxx = (stt[b] - stt[a]) - sumT * sumT / m;
        const double sxy = (sty[b] - sty[a]) - sumT * sumY / m;
        if (m >= 2 && sxx > 0) seen[k] += tau_s * sxy / sxx;
    }
    return seen;
}

}  // namespace driftlab::diagnosis
