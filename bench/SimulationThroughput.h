#pragma once
// The simulation throughput figure of driftlab-bench and of the
// simulation_bench target: an 8-hour moving-state campaign on a 200-cell screw
// stepped at 1 s (5.76 million cell-steps), timed over a few repetitions.

#include <vector>

#include "core/domain/Run.h"
#include "core/physics/ScrewThermalParameters.h"

namespace driftlab::bench {

/// The benchmark campaign: 8 h of reciprocating 210–490 mm at 8000 mm/min in
/// 10 min blocks, each followed by a 100 s dwell (the dwell is a segment, as in
/// a moving-state programme).
struct BenchmarkCampaign {
    static constexpr double kDuration_s = 8 * 3600;
    static constexpr double kStep_s = 1;
    static constexpr int kCells = 200;

    physics::ScrewThermalParameters parameters;  ///< the default machine screw, 200 cells
    std::vector<MotionSegment> motion;

    BenchmarkCampaign();
    long steps() const { return static_cast<long>(kDuration_s / kStep_s); }
    double cellSteps() const { return static_cast<double>(steps()) * kCells; }
    /// Simulates the whole campaign from 20 °C with the room drifting to 22 °C;
    /// returns the free-end thermal error, µm, so the work cannot be elided.
    double run() const;
};

struct SimulationThroughput {
    double cell_steps_per_s = 0;  ///< median over the repetitions
    double campaign_ms = 0;       ///< median wall time of one campaign
    int repetitions = 0;
};

/// Runs the benchmark campaign `repetitions` times (at least one) and returns
/// the medians. Takes about 0.1 s per repetition on a current desktop core.
SimulationThroughput measureSimulationThroughput(int repetitions = 5);

}  // namespace driftlab::bench
