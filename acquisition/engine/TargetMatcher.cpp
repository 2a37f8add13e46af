#include "acquisition/engine/TargetMatcher.h"

#include <cmath>

namespace driftlab::engine {

TargetMatcher::TargetMatcher(std::vector<rig::MeasurementEvent> planned, double tolerance_mm)
    : m_planned(std::move(planned)), m_tolerance_mm(tolerance_mm) {}

std::optional<rig::MeasurementEvent> TargetMatcher::match(double position_mm) {
    for (std::size_t k = m_next; k < m_planned.size(); ++k) {
        if (std::abs(m_planned[k].target_mm - position_mm) > m_tolerance_mm) continue;
        m_next = k + 1;
        m_lastMatched_s = m_planned[k].time_s;
        return m_planned[k];
    }
    return std::nullopt;
}

void TargetMatcher::replan(std::vector<rig::MeasurementEvent> planned) {
    m_planned = std::move(planned);
    m_next = 0;
    if (!m_lastMatched_s) return;
    while (m_next < m_planned.size() && m_planned[m_next].time_s <= *m_lastMatched_s) ++m_next;
}

}  // namespace driftlab::engine
