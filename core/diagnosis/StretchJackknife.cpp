#include "core/diagnosis/StretchJackknife.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/SpecialFunctions>

namespace driftlab::diagnosis {
namespace {

/// The time span of one run's residuals, over every kind of reading.
std::pair<double, double> span(const models::ReadingResiduals& r) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& p : r.points) lo = std::min(lo, p.time_s), hi = std::max(hi, p.time_s);
    for (const auto& s : r.sensors)
        if (!s.time_s.empty())
            lo = std::min(lo, s.time_s.front()), hi = std::max(hi, s.time_s.back());
    return {lo, hi};
}

/// Adds r² of the quantity into its stretch of `sums` (run `run`).
void addRun(const models::ReadingResiduals& r, const QString& channel, int perRun,
            std::pair<double, double> runSpan, std::size_t run, std::vector<double>& sums) {
    const auto add = [&](double t, double v) {
        sums[run * perRun + stretchOf(t, runSpan.first, runSpan.second, perRun)] += v * v;
    };
    if (channel.isEmpty())
        for (std::size_t i = 0; i < r.error_um.size() && i < r.points.size(); ++i)
            add(r.points[i].time_s, r.error_um[i]);
    for (const auto& s : r.sensors)
        if (!channel.isEmpty() && s.channel_id == channel)
            for (std::size_t i = 0; i < s.residual_K.size() && i < s.time_s.size(); ++i)
                add(s.time_s[i], s.residual_K[i]);
}

/// The gain without stretch `k` (k < 0: with every stretch).
double gainWithout(const StretchSquares& s, int k) {
    double before = 0, after = 0;
    for (std::size_t i = 0; i < s.before.size(); ++i)
        if (int(i) != k) before += s.before[i], after += s.after[i];
    return before > 0 ? 1 - std::sqrt(after / before) : 0;
}

}  // namespace

int stretchOf(double time_s, double first_s, double last_s, int perRun) {
    const double width = (last_s - first_s) / perRun;
    return width > 0 ? std::clamp(int((time_s - first_s) / width), 0, perRun - 1) : 0;
}

StretchSquares stretchSquares(const std::vector<models::ReadingResiduals>& before,
                              const std::vector<models::ReadingResiduals>& after,
                              const QString& channel, int perRun) {
    StretchSquares s;
    const std::size_t runs = std::min(before.size(), after.size());
    s.before.assign(runs * perRun, 0.0);
    s.after.assign(runs * perRun, 0.0);
    for (std::size_t r = 0; r < runs; ++r) {
        // The stretches of a run are where the base model's readings are, so
        // that every candidate's are the same.
        const auto runSpan = span(before[r]);
        addRun(before[r], channel, perRun, runSpan, r, s.before);
        addRun(after[r], channel, perRun, runSpan, r, s.after);
    }
    return s;
}

double studentTCdf(double t, double dof) {
    if (!(dof > 0) || std::isnan(t)) return std::nan("");
    if (std::isinf(t)) return t > 0 ? 1.0 : 0.0;
    // P(|T| > |t|) = I_x(dof/2, 1/2) with x = dof / (dof + t²).
    Eigen::Array<double, 1, 1> a, b, x;
    a << dof / 2;
    b << 0.5;
    x << dof / (dof + t * t);
    const double tail = 0.5 * Eigen::betainc(a, b, x)(0);
    return t > 0 ? 1 - tail : tail;
}

double probabilityLarger(const StretchSquares& a, const StretchSquares* b) {
    const auto difference = [&](int k) { return gainWithout(a, k) - (b ? gainWithout(*b, k) : 0); };
    // Only stretches with readings of either quantity are evidence.
    std::vector<int> used;
    for (std::size_t i = 0; i < a.before.size(); ++i)
        if (a.before[i] > 0 || (b && i < b->before.size() && b->before[i] > 0))
            used.push_back(int(i));
    const double full = difference(-1);
    const double n = double(used.size());
    std::vector<double> leftOut;
    double mean = 0;
    for (int k : used) {
        leftOut.push_back(difference(k));
        mean += leftOut.back() / n;
    }
    double variance = 0;
    for (double d : leftOut) variance += (d - mean) * (d - mean);
    const double se = std::sqrt(variance * (n - 1) / n);
    // Fewer than two stretches, or no spread: the sign is all there is.
    if (used.size() < 2 || !(se > 0)) return full > 0 ? 1.0 : full < 0 ? 0.0 : 0.5;
    return studentTCdf(full / se, n - 1);
}

}  // namespace driftlab::diagnosis
