#include "acquisition/live/LiveReadings.h"

namespace driftlab::live {

void LiveReadings::append(const PositioningMeasurement& reading) {
    std::lock_guard lock(m_mutex);
    m_readings.push_back(reading);
}

std::vector<PositioningMeasurement> LiveReadings::since(std::size_t from) const {
    std::lock_guard lock(m_mutex);
    if (from >= m_readings.size()) return {};
    return {m_readings.begin() + std::ptrdiff_t(from), m_readings.end()};
}

std::size_t LiveReadings::size() const {
    std::lock_guard lock(m_mutex);
    return m_readings.size();
}

}  // namespace driftlab::live
