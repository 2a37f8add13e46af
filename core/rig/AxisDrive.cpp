#include "core/rig/AxisDrive.h"

#include <algorithm>
#include <cmath>

namespace driftlab::rig {

double AxisDrive::speed_rad_s(const MotionSegment& s) const {
    const double span = s.end_s - s.start_s;
    if (span <= 0 || s.isDwell()) return 0;
    const double v_mm_s = (s.to_mm - s.from_mm) / span;
    return 2 * M_PI * v_mm_s / lead_mm_;
}

double AxisDrive::steadyTorque_Nm(double omega) const {
    if (omega == 0) return 0;
    return std::copysign(spec_.coulomb_Nm, omega) + spec_.viscous_Nm_per_rad_s * omega;
}

std::size_t AxisDrive::segmentAt(std::span<const MotionSegment> motion, double time_s) {
    if (cursor_ >= motion.size() || motion[cursor_].start_s > time_s) cursor_ = 0;
    while (cursor_ + 1 < motion.size() && motion[cursor_].end_s <= time_s) ++cursor_;
    return cursor_;
}

double AxisDrive::torqueSquaredIntegral(std::span<const MotionSegment> motion, double t0,
                                        double t1) {
    double integral = 0;
    for (std::size_t k = segmentAt(motion, t0); k < motion.size() && motion[k].start_s < t1; ++k) {
        const double a = std::max(t0, motion[k].start_s), b = std::min(t1, motion[k].end_s);
        if (b <= a) continue;
        const double omega = speed_rad_s(motion[k]);
        const double steady = steadyTorque_Nm(omega);
        integral += steady * steady * (b - a);
        // The speed change at the start of a segment: inertia torque for t_acc.
        if (motion[k].start_s >= t0) {
            const double before = k > 0 ? speed_rad_s(motion[k - 1]) : 0.0;
            const double inertia =
                spec_.inertia_kg_m2 * (omega - before) / spec_.acceleration_time_s;
            integral += inertia * inertia * spec_.acceleration_time_s;
        }
    }
    return integral;
}

double AxisDrive::loggedTorque_Nm(double torqueSquaredIntegral_N2m2s, double interval_s) {
    const double rms = interval_s > 0 ? std::sqrt(torqueSquaredIntegral_N2m2s / interval_s) : 0.0;
    return std::max(0.0, rms + noise_(rng_) * spec_.torque_noise_Nm);
}

}  // namespace driftlab::rig
