#pragma once
// Motor torque of the feed drive from the motion: Coulomb friction and viscous
// drag while moving, inertia torque while reversing. Used for the logged
// torque channel and for the motor heat (∝ torque²) the rig can hide.

#include <random>
#include <span>

#include "core/domain/Run.h"
#include "core/rig/RigSpec.h"

namespace driftlab::rig {

class AxisDrive {
public:
    AxisDrive(const AxisDriveSpec& spec, double lead_mm, unsigned seed)
        : m_spec(spec), m_lead_mm(lead_mm), m_rng(seed) {}

    /// ∫ torque² dt over [t0, t1], N²·m²·s.
    double torqueSquaredIntegral(std::span<const MotionSegment> motion, double t0, double t1);
    /// The logged torque: the RMS over the sample interval, as drives report
    /// their thermal load (a 10 s snapshot would miss the reversals), with noise, N·m.
    double loggedTorque_Nm(double torqueSquaredIntegral_N2m2s, double interval_s);

private:
    double speed_rad_s(const MotionSegment& s) const;  ///< signed
    double steadyTorque_Nm(double omega) const;
    std::size_t segmentAt(std::span<const MotionSegment> motion, double time_s);

    AxisDriveSpec m_spec;
    double m_lead_mm;
    std::mt19937_64 m_rng;
    std::normal_distribution<double> m_noise{0.0, 1.0};
    std::size_t m_cursor = 0;
};

}  // namespace driftlab::rig
