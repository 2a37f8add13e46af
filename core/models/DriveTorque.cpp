#include "core/models/DriveTorque.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/models/RunDataAccess.h"

namespace driftlab::models {
namespace {

constexpr int kFeatures = 5;

// Moving fraction, mean |ω|, mean ω², Σ|Δω|/dt and ΣΔω²/dt of each step.
Eigen::MatrixXd motionFeatures(const std::vector<MotionSegment>& motion, double lead_mm,
                               std::size_t steps, double dt_s) {
    Eigen::MatrixXd f = Eigen::MatrixXd::Zero(Eigen::Index(steps), kFeatures);
    auto speed = [&](const MotionSegment& s) {
        const double span = s.end_s - s.start_s;
        return span > 0 ? 2 * std::numbers::pi * std::abs(s.to_mm - s.from_mm) / span / lead_mm
                        : 0.0;
    };
    auto stepOf = [&](double t) {
        return std::min(steps - 1, std::size_t(std::max(0.0, t) / dt_s));
    };
    double before = 0;
    for (const MotionSegment& s : motion) {
        const double omega = speed(s);
        if (s.start_s < double(steps) * dt_s) {
            const auto k = Eigen::Index(stepOf(s.start_s));
            const double change = std::abs(omega - before);
            f(k, 3) += change / dt_s;
            f(k, 4) += change * change / dt_s;
        }
        before = omega;
        if (omega == 0) continue;
        // Spread the segment's time over the steps it covers.
        for (std::size_t k = stepOf(s.start_s); k < steps && double(k) * dt_s < s.end_s; ++k) {
            const double overlap =
                std::min(s.end_s, double(k + 1) * dt_s) - std::max(s.start_s, double(k) * dt_s);
            if (overlap <= 0) continue;
            const double w = overlap / dt_s;
            f(Eigen::Index(k), 0) += w;
            f(Eigen::Index(k), 1) += w * omega;
            f(Eigen::Index(k), 2) += w * omega * omega;
        }
    }
    return f;
}

std::vector<double> sampleMeans(const Signal& squared, std::size_t steps, double dt_s,
                                const QString& runId) {
    std::vector<double> mean(steps);
    const std::vector<double>& t = squared.time_s;
    std::size_t i = 0;
    for (std::size_t k = 0; k < steps; ++k) {
        const double end = double(k + 1) * dt_s;
        double sum = 0;
        std::size_t count = 0;
        for (; i < t.size() && t[i] < end; ++i)
            if (t[i] >= double(k) * dt_s) sum += squared.value[i], ++count;
        mean[k] = count > 0 ? sum / double(count)
                            : valueAt(squared, (double(k) + 0.5) * dt_s, 1e9, runId);
    }
    return mean;
}

// Every coefficient is a square or a product of positive drive constants, so
// none may be negative: without that the five collinear features of a run at
// one speed fit the noise with coefficients of ±1000. With five features the
// exact non-negative least squares is the best of the 31 subsets' fits whose
// coefficients are all positive, from one normal matrix.
Eigen::VectorXd nonNegativeLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
    // Scaled columns: ω² and Δω² are thousands of times the moving fraction.
    const Eigen::VectorXd scale = a.colwise().norm().transpose().cwiseMax(1e-300);
    const Eigen::MatrixXd scaled = a * scale.cwiseInverse().asDiagonal();
    const Eigen::MatrixXd normal = scaled.transpose() * scaled;
    const Eigen::VectorXd moment = scaled.transpose() * b;
    Eigen::VectorXd best = Eigen::VectorXd::Zero(kFeatures);
    double bestCost = 0;  // the cost of all-zero coefficients, less bᵀb
    for (unsigned subset = 1; subset < (1u << kFeatures); ++subset) {
        int columns[kFeatures], n = 0;
        for (int c = 0; c < kFeatures; ++c)
            if (subset & (1u << c)) columns[n++] = c;
        Eigen::MatrixXd subNormal(n, n);
        Eigen::VectorXd subMoment(n);
        for (int i = 0; i < n; ++i) {
            subMoment(i) = moment(columns[i]);
            for (int j = 0; j < n; ++j) subNormal(i, j) = normal(columns[i], columns[j]);
        }
        const Eigen::VectorXd x = subNormal.ldlt().solve(subMoment);
        if (!x.allFinite() || (x.array() < 0).any()) continue;
        const double cost = -x.dot(subMoment);  // at the optimum xᵀNx = xᵀm
        if (cost < bestCost) {
            bestCost = cost;
            best.setZero();
            for (int i = 0; i < n; ++i) best(columns[i]) = x(i);
        }
    }
    return best.cwiseQuotient(scale);
}

}  // namespace

std::vector<double> meanTorqueSquaredPerStep(const RunData& run,
                                             const std::vector<MotionSegment>& motion,
                                             std::size_t steps, double dt_s) {
    Signal squared = run.torque_Nm;
    for (double& v : squared.value) v *= v;
    // A log that never goes negative is an RMS (a drive's I²t channel): it
    // already holds the mean of τ² over each interval.
    const bool rms = std::ranges::none_of(run.torque_Nm.value, [](double v) { return v < 0; });
    if (rms || run.motion.empty() || !run.screw || squared.time_s.size() < 4 * kFeatures ||
        steps == 0)
        return sampleMeans(squared, steps, dt_s, run.run_id);

    const Eigen::MatrixXd features = motionFeatures(motion, run.screw->lead_mm, steps, dt_s);
    Eigen::MatrixXd a(Eigen::Index(squared.time_s.size()), kFeatures);
    Eigen::VectorXd b(a.rows());
    Eigen::Index rows = 0;
    for (std::size_t i = 0; i < squared.time_s.size(); ++i) {
        const double t = squared.time_s[i];
        if (t < 0 || t >= double(steps) * dt_s) continue;
        a.row(rows) = features.row(Eigen::Index(t / dt_s));
        b(rows++) = squared.value[i];
    }
    const Eigen::VectorXd theta = nonNegativeLeastSquares(a.topRows(rows), b.head(rows));
    const Eigen::VectorXd fitted = features * theta;
    std::vector<double> mean(steps);
    for (std::size_t k = 0; k < steps; ++k) mean[k] = std::max(0.0, fitted(Eigen::Index(k)));
    return mean;
}

}  // namespace driftlab::models
