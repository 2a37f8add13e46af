#pragma once
// The interferometer readings of the run in progress, for the live dashboard:
// the engine's thread appends, any thread reads what came since its cursor.
// Readings are few (one per planned target and cycle), so a short mutex and a
// vector are enough; the store stays the record.

#include <mutex>
#include <vector>

#include "core/domain/Run.h"

namespace driftlab::live {

class LiveReadings {
public:
    void append(const PositioningMeasurement& reading);
    /// Readings from index `from` on (copies).
    std::vector<PositioningMeasurement> since(std::size_t from) const;
    std::size_t size() const;

private:
    mutable std::mutex m_mutex;
    std::vector<PositioningMeasurement> m_readings;  // guarded by m_mutex
};

}  // namespace driftlab::live
