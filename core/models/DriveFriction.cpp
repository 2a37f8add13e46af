#include "core/models/DriveFriction.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {
namespace {

/// Signed screw speed ω from `time_s` on, rad/s.
struct SpeedStep {
    double time_s;
    double omega;
};

/// The motion programme as a piecewise-constant signed speed (standstill
/// between segments); empty without motion or lead.
std::vector<SpeedStep> speedProfile(const RunData& run) {
    std::vector<SpeedStep> steps;
    if (run.motion.empty() || !run.lead_mm() || !(*run.lead_mm() > 0)) return steps;
    const double scale = 2 * std::numbers::pi / 60 / *run.lead_mm();
    auto segments = run.motion;
    std::stable_sort(segments.begin(), segments.end(),
                     [](const auto& a, const auto& b) { return a.start_s < b.start_s; });
    for (std::size_t j = 0; j < segments.size(); ++j) {
        const MotionSegment& s = segments[j];
        const double omega =
            s.isDwell() ? 0.0 : std::copysign(std::abs(s.feed_mm_min) * scale, s.to_mm - s.from_mm);
        steps.push_back({s.start_s, omega});
        if (j + 1 == segments.size() || segments[j + 1].start_s > s.end_s + 1e-6)
            steps.push_back({s.end_s, 0.0});
    }
    return steps;
}

/// What the motion did over one torque sample's interval.
struct IntervalMotion {
    double moving = 0;   ///< share of the interval spent moving
    double speed = 0;    ///< mean |ω|, rad/s
    double speed2 = 0;   ///< mean ω², rad²/s²
    double changes = 0;  ///< Σ (Δω)² / Δt over the speed changes in it, rad²/s³
};

/// The motion over (t[i−1], t[i]] for every i ≥ 1, in one sweep.
std::vector<IntervalMotion> intervalMotion(const std::vector<SpeedStep>& p,
                                           const std::vector<double>& t) {
    std::vector<IntervalMotion> out(t.size());
    std::size_t k = 0;  // first step after the interval's start
    for (std::size_t i = 1; i < t.size(); ++i) {
        const double a = t[i - 1], b = t[i], dt = b - a;
        if (!(dt > 0)) continue;
        while (k < p.size() && p[k].time_s <= a) ++k;
        IntervalMotion& m = out[i];
        double omega = k > 0 ? p[k - 1].omega : 0.0, from = a;
        for (std::size_t j = k; j <= p.size(); ++j) {
            const double to = j < p.size() ? std::min(b, p[j].time_s) : b;
            const double span = std::max(0.0, to - from);
            m.moving += omega != 0 ? span : 0;
            m.speed += std::abs(omega) * span;
            m.speed2 += omega * omega * span;
            if (j == p.size() || p[j].time_s > b) break;
            m.changes += (p[j].omega - omega) * (p[j].omega - omega);
            omega = p[j].omega;
            from = p[j].time_s;
        }
        m.moving /= dt;
        m.speed /= dt;
        m.speed2 /= dt;
        m.changes /= dt;
    }
    return out;
}

}  // namespace

double fitInertiaTerm(const std::vector<RunData>& runs) {
    std::vector<std::array<double, 5>> rows;  // f, ⟨|ω|⟩, ⟨ω²⟩, changes, τ²
    for (const RunData& run : runs) {
        const auto profile = speedProfile(run);
        if (profile.empty() || run.torque_Nm.empty()) continue;
        const auto motion = intervalMotion(profile, run.torque_Nm.time_s);
        for (std::size_t i = 1; i < motion.size(); ++i) {
            const double tau = run.torque_Nm.value[i];
            rows.push_back({motion[i].moving, motion[i].speed, motion[i].speed2, motion[i].changes,
                            tau * tau});
        }
    }
    if (rows.size() < 8) return 0;
    Eigen::MatrixXd X(Eigen::Index(rows.size()), 4);
    Eigen::VectorXd y(Eigen::Index(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
        for (int c = 0; c < 4; ++c) X(Eigen::Index(r), c) = rows[r][std::size_t(c)];
        y(Eigen::Index(r)) = rows[r][4];
    }
    // Columns scaled to unit norm: ⟨ω²⟩ and Σ(Δω)²/Δt are orders of magnitude apart.
    const Eigen::VectorXd norms = X.colwise().norm().cwiseMax(1e-300);
    const Eigen::VectorXd b =
        (X * norms.cwiseInverse().asDiagonal()).colPivHouseholderQr().solve(y).cwiseQuotient(norms);
    return std::isfinite(b(3)) ? std::max(0.0, b(3)) : 0.0;
}

PiecewiseInput frictionPower(const RunData& run, const PiecewiseInput& screwSpeed, double until_s,
                             double inertiaTerm, const QString& model) {
    if (run.torque_Nm.empty())
        throw ModelError(QStringLiteral("model '%1' needs the motor torque: run '%2' has no "
                                        "samples in %3")
                             .arg(model, run.run_id, describeSignal(run.torque_Nm)));
    requireCoverage(run, run.torque_Nm, until_s);
    const auto profile = inertiaTerm > 0 ? speedProfile(run) : std::vector<SpeedStep>{};
    if (profile.empty()) {
        PiecewiseInput power = screwSpeed;
        for (std::size_t i = 0; i < power.time_s.size(); ++i)
            power.value[i] *=
                std::abs(valueAt(run.torque_Nm, power.time_s[i], run.max_gap_s, run.run_id));
        return power;
    }
    // Each sample stands for the interval before it: its value is held from
    // the previous sample's time.
    const auto& t = run.torque_Nm.time_s;
    const auto motion = intervalMotion(profile, t);
    PiecewiseInput power;
    power.time_s.push_back(0);
    power.value.push_back(0);
    for (std::size_t i = 1; i < t.size(); ++i) {
        const double tau = run.torque_Nm.value[i];
        // RMS over the interval → friction torque while moving.
        const double meanSquare = std::max(0.0, tau * tau - inertiaTerm * motion[i].changes);
        const double friction =
            motion[i].moving > 0 ? std::sqrt(meanSquare / motion[i].moving) : 0.0;
        power.time_s.push_back(std::max(t[i - 1], power.time_s.back()));
        power.value.push_back(friction * motion[i].speed);
    }
    power.time_s.push_back(t.back());
    power.value.push_back(0);
    return power;
}

}  // namespace driftlab::models
