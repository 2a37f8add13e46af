#pragma once
// The motion programme of a moving-state run (ISO 230-3 style, as in the
// cross-state studies): warm-up blocks of reciprocating over a range at a
// feed, each followed by a bidirectional interferometer pass over the targets,
// then a cool-down with a pass at fixed intervals. Cycle 0 at time 0 is the
// cold reference pass.

#include <vector>

#include "core/domain/Run.h"

namespace driftlab::rig {

struct MovingStateSpec {
    double feed_mm_min = 8000;
    RangeMm range_mm{210, 490};
    double warmup_s = 7200;
    double cooldown_s = 3600;
    double block_s = 600;              ///< reciprocating time between passes
    double cooldown_interval_s = 600;  ///< time between passes while cooling
    std::vector<double> targets_mm;    ///< interferometer targets, ascending
    double pass_feed_mm_min = 3000;    ///< feed between targets during a pass
    double dwell_s = 3;                ///< standstill at each target; reading at its middle
    double overrun_mm = 5;             ///< overrun before reversing, as ISO 230-2 asks
};

/// One interferometer reading the programme asks for.
struct MeasurementEvent {
    double time_s = 0;
    int cycle = 0;
    double target_mm = 0;
    Direction direction = Direction::Positive;
};

struct Programme {
    std::vector<MotionSegment> motion;
    std::vector<MeasurementEvent> measurements;
    double duration_s = 0;
};

/// `count` targets equally spaced over the travel with a margin for the overrun.
std::vector<double> equallySpacedTargets(const RangeMm& travel_mm, int count, double margin_mm);

/// Builds the programme; throws std::invalid_argument on a spec that cannot run
/// (non-positive feed or durations, an empty range, no targets).
Programme buildMovingStateProgramme(const MovingStateSpec& spec);

/// Nut position and signed feed at a time, from a programme's motion.
struct AxisState {
    double position_mm = 0;
    double feed_mm_min = 0;
};
AxisState axisStateAt(const std::vector<MotionSegment>& motion, double time_s);

}  // namespace driftlab::rig
