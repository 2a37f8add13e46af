#pragma once
// Which planned reading an interferometer reading of a real rig is. The
// machine runs its own NC programme, so its clock and the plan's drift apart:
// a reading is matched by position and order, not by time. It is the next
// planned measurement (in plan order, from the one after the last matched)
// whose target is within the tolerance of the reading's position; the planned
// measurements it skips are not matched later (a reading lost in an outage
// stays missing rather than shifting the cycles of the readings after it).

#include <optional>
#include <vector>

#include "core/rig/MovingStateProgramme.h"

namespace driftlab::engine {

class TargetMatcher {
public:
    /// Position tolerance of a match, mm: far below any target spacing, far
    /// above an axis's positioning error.
    static constexpr double kDefaultTolerance_mm = 0.05;

    explicit TargetMatcher(std::vector<rig::MeasurementEvent> planned,
                           double tolerance_mm = kDefaultTolerance_mm);

    /// The planned measurement `position_mm` is, consumed; nullopt when no
    /// planned target ahead is within the tolerance.
    std::optional<rig::MeasurementEvent> match(double position_mm);

    /// A new plan (ISO 230-3 warm-up ended early): matching goes on after the
    /// planned time of the last match.
    void replan(std::vector<rig::MeasurementEvent> planned);

    double tolerance_mm() const { return m_tolerance_mm; }

private:
    std::vector<rig::MeasurementEvent> m_planned;
    double m_tolerance_mm;
    std::size_t m_next = 0;  ///< first planned measurement not yet matched or skipped
    std::optional<double> m_lastMatched_s;
};

}  // namespace driftlab::engine
