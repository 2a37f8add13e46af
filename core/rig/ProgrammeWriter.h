#pragma once
// Writes a rig::Programme move by move, keeping track of where the nut is and
// what time it is. Shared by the moving-state programme and the ISO 230-2
// positioning programme so both time their motion the same way.

#include <cmath>

#include "core/rig/MovingStateProgramme.h"

namespace driftlab::rig {

/// Times on a whole microsecond, so that sums of stroke times do not leave
/// 2858.4000000000046 s in the logs.
inline double onMicrosecond(double time_s) {
    return std::round(time_s * 1e6) / 1e6;
}

class ProgrammeWriter {
public:
    ProgrammeWriter(Programme& p, double start_mm) : m_p(p), m_position_mm(start_mm) {}

    double time() const { return m_time_s; }
    double position() const { return m_position_mm; }

    void moveTo(double to_mm, double feed_mm_min) {
        if (to_mm == m_position_mm) return;
        const double duration_s = std::abs(to_mm - m_position_mm) / feed_mm_min * 60.0;
        const double signed_feed = to_mm > m_position_mm ? feed_mm_min : -feed_mm_min;
        const double end_s = onMicrosecond(m_time_s + duration_s);
        m_p.motion.push_back({m_time_s, end_s, m_position_mm, to_mm, signed_feed});
        m_time_s = end_s;
        m_position_mm = to_mm;
    }
    void dwell(double duration_s) {
        if (duration_s <= 0) return;
        // Merge consecutive dwells so the motion list stays short.
        if (!m_p.motion.empty() && m_p.motion.back().isDwell() &&
            m_p.motion.back().end_s == m_time_s && m_p.motion.back().from_mm == m_position_mm)
            m_p.motion.back().end_s = onMicrosecond(m_time_s + duration_s);
        else
            m_p.motion.push_back(
                {m_time_s, onMicrosecond(m_time_s + duration_s), m_position_mm, m_position_mm, 0});
        m_time_s = m_p.motion.back().end_s;
    }
    void dwellUntil(double time_s) { dwell(time_s - m_time_s); }
    /// A reading in the middle of a dwell (the moving-state passes).
    void measure(int cycle, double target_mm, Direction direction, double dwell_s) {
        m_p.measurements.push_back(
            {onMicrosecond(m_time_s + dwell_s / 2), cycle, target_mm, direction});
        dwell(dwell_s);
    }
    /// A reading at the end of a dwell (ISO 230-2: the axis settles, then it is read).
    void measureAfterDwell(int cycle, double target_mm, Direction direction, double dwell_s) {
        dwell(dwell_s);
        m_p.measurements.push_back({m_time_s, cycle, target_mm, direction});
    }

private:
    Programme& m_p;
    double m_position_mm;
    double m_time_s = 0;
};

}  // namespace driftlab::rig
