#include "core/rig/AxisDrive.h"

#include <algorithm>
#include <cmath>

namespace driftlab::rig {

double AxisDrive::speed_rad_s(const MotionSegment& s) const {
    const double span = s.end_s - s.start_s;
    if (span <= 0 || s.isDwell()) return 0;
    const double v_mm_s = (s.to_mm - s.from_mm) / span;
    return 2 * M_PI * v_mm_s / m_lead_mm;
}

double AxisDrive::steadyTorque_Nm(double omega) const {
    if (omega == 0) return 0;
    return std::copysign(m_spec.coulomb_Nm, omega) + m_spec.viscous_Nm_per_rad_s * omega;
}

std::size_t AxisDrive::segmentAt(std::span<const MotionSegment> motion, double time_s) {
    if (m_cursor >= motion.size() || motion[m_cursor].start_s > time_s) m_cursor = 0;
    while (m_cursor + 1 < motion.size() && motion[m_cursor].end_s <= time_s) ++m_cursor;
    return m_cursor;
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
                m_spec.inertia_kg_m2 * (omega - before) / m_spec.acceleration_time_s;
            integral += inertia * inertia * m_spec.acceleration_time_s;
        }
    }
    return integral;
}

double AxisDrive::loggedTorque_Nm(double torqueSquaredIntegral_N2m2s, double interval_s) {
    const double rms = interval_s > 0 ? std::sqrt(torqueSquaredIntegral_N2m2s / interval_s) : 0.0;
    return std::max(0.0, rms + m_noise(m_rng) * m_spec.torque_noise_Nm);
}

}  // namespace driftlab::rig
