#include "core/models/DriveTorque.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/models/RunDataAccess.h"

namespace driftlab::models {
namespace {

// Of each step: moving fraction, mean |ω|, mean ω², then Σ Δω²/d per second
// over the speed changes in it, d the time the change took: ∫α² dt, the
// inertia torque's square over J², for a motion written finely enough.
constexpr int kSteady = 3;
constexpr double kFitStep_s = 2;

/// Signed: a reversal changes the speed by twice its size.
double velocityOf(const MotionSegment& s, double lead_mm) {
    const double span = s.end_s - s.start_s;
    return span > 0 ? 2 * std::numbers::pi * (s.to_mm - s.from_mm) / span / lead_mm : 0.0;
}

Eigen::MatrixXd motionFeatures(const std::vector<MotionSegment>& motion, double lead_mm,
                               std::size_t steps, double dt_s) {
    Eigen::MatrixXd f = Eigen::MatrixXd::Zero(Eigen::Index(steps), kSteady + 1);
    auto stepOf = [&](double t) {
        return std::min(steps - 1, std::size_t(std::max(0.0, t) / dt_s));
    };
    double before = 0, beforeSpan = 0;
    for (const MotionSegment& s : motion) {
        const double velocity = velocityOf(s, lead_mm), omega = std::abs(velocity);
        const double span = s.end_s - s.start_s;
        if (s.start_s < double(steps) * dt_s && velocity != before) {
            const auto k = Eigen::Index(stepOf(s.start_s));
            const double change = velocity - before;
            const double took =
                std::max(1e-3, before == 0 && beforeSpan == 0 ? span : std::min(span, beforeSpan));
            f(k, kSteady) += change * change / took / dt_s;
        }
        before = velocity;
        beforeSpan = span;
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

Eigen::VectorXd steadySquare(const Eigen::MatrixXd& f, const DriveTorqueModel& d) {
    const double c = d.coulomb_Nm, b = d.viscous_Nm_per_rad_s;
    return c * c * f.col(0) + 2 * c * b * f.col(1) + b * b * f.col(2);
}

std::size_t fitSteps(const RunData& run) {
    return std::size_t(
        std::ceil(std::max(run.torque_Nm.time_s.back(), run.motion.back().end_s) / kFitStep_s));
}

std::vector<double> sampleMeans(const Signal& torque, std::size_t steps, double dt_s,
                                const QString& runId) {
    Signal squared = torque;
    for (double& v : squared.value) v *= v;
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
                            : bridgedValueAt(squared, (double(k) + 0.5) * dt_s, runId);
    }
    return mean;
}

}  // namespace

bool instantaneousTorqueLog(const RunData& run) {
    return run.screw && !run.motion.empty() &&
           std::ranges::any_of(run.torque_Nm.value, [](double v) { return v < 0; });
}

std::optional<DriveTorqueModel> identifyDriveTorque(std::span<const RunData> runs) {
    // 1. Held speed: samples at least 0.25 s inside a segment of 1 s or more.
    std::vector<double> speed, magnitude;
    for (const RunData& run : runs) {
        if (!instantaneousTorqueLog(run)) continue;
        std::size_t s = 0;
        for (std::size_t i = 0; i < run.torque_Nm.time_s.size(); ++i) {
            const double t = run.torque_Nm.time_s[i];
            while (s < run.motion.size() && run.motion[s].end_s < t) ++s;
            if (s == run.motion.size()) break;
            const MotionSegment& m = run.motion[s];
            if (m.isDwell() || m.end_s - m.start_s < 1 || t - m.start_s < 0.25 ||
                m.end_s - t < 0.25)
                continue;
            speed.push_back(std::abs(velocityOf(m, run.screw->lead_mm)));
            magnitude.push_back(std::abs(run.torque_Nm.value[i]));
        }
    }
    if (speed.size() < 20) return std::nullopt;
    const Eigen::Map<const Eigen::VectorXd> omega(speed.data(), Eigen::Index(speed.size()));
    const Eigen::Map<const Eigen::VectorXd> tau(magnitude.data(), omega.size());
    DriveTorqueModel drive;
    // At one held speed F_c and b cannot be told apart: all of it is F_c.
    if (omega.maxCoeff() < 1.1 * omega.minCoeff()) {
        drive.coulomb_Nm = tau.mean();
    } else {
        Eigen::MatrixXd held(omega.size(), 2);
        held.col(0).setOnes();
        held.col(1) = omega;
        const Eigen::Vector2d line = held.colPivHouseholderQr().solve(tau);
        drive.coulomb_Nm = std::max(0.0, line(0));
        drive.viscous_Nm_per_rad_s = std::max(0.0, line(1));
    }

    // 2. What the speed changes add, J²·∫α², on a 2 s grid over all runs at
    // once: the least-squares J² of the squared samples' excess over (1).
    double moment = 0, norm = 0;
    for (const RunData& run : runs) {
        if (!instantaneousTorqueLog(run)) continue;
        const std::size_t steps = fitSteps(run);
        const Eigen::MatrixXd f = motionFeatures(run.motion, run.screw->lead_mm, steps, kFitStep_s);
        const Eigen::VectorXd steady = steadySquare(f, drive);
        const auto& t = run.torque_Nm.time_s;
        for (std::size_t i = 0; i < t.size(); ++i) {
            const auto k =
                Eigen::Index(std::min(steps - 1, std::size_t(std::max(0.0, t[i]) / kFitStep_s)));
            const double tau = run.torque_Nm.value[i];
            moment += f(k, kSteady) * (tau * tau - steady(k));
            norm += f(k, kSteady) * f(k, kSteady);
        }
    }
    drive.inertia_squared_kg2m4 = norm > 0 ? std::max(0.0, moment / norm) : 0.0;
    return drive;
}

std::vector<double> meanTorqueSquaredPerStep(const RunData& run,
                                             const std::vector<MotionSegment>& motion,
                                             std::size_t steps, double dt_s) {
    if (!run.drive_torque || !run.screw || steps == 0)
        return sampleMeans(run.torque_Nm, steps, dt_s, run.run_id);
    const DriveTorqueModel& d = *run.drive_torque;
    const Eigen::MatrixXd f = motionFeatures(motion, run.screw->lead_mm, steps, dt_s);
    const Eigen::VectorXd square = steadySquare(f, d) + d.inertia_squared_kg2m4 * f.col(kSteady);
    std::vector<double> mean(steps);
    for (std::size_t k = 0; k < steps; ++k) mean[k] = std::max(0.0, square(Eigen::Index(k)));
    return mean;
}

}  // namespace driftlab::models
