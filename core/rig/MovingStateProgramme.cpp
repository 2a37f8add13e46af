#include "core/rig/MovingStateProgramme.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/rig/ProgrammeWriter.h"

namespace driftlab::rig {
namespace {

void interferometerPass(ProgrammeWriter& w, const MovingStateSpec& spec, int cycle,
                        double park_mm) {
    const auto& targets = spec.targets_mm;
    const double feed = spec.pass_feed_mm_min;
    // Approach the first target from below and the reverse run from above, so
    // every reading of one direction is taken after the same kind of approach.
    w.moveTo(targets.front() - spec.overrun_mm, feed);
    for (double x : targets) {
        w.moveTo(x, feed);
        w.measure(cycle, x, Direction::Positive, spec.dwell_s);
    }
    w.moveTo(targets.back() + spec.overrun_mm, feed);
    for (auto it = targets.rbegin(); it != targets.rend(); ++it) {
        w.moveTo(*it, feed);
        w.measure(cycle, *it, Direction::Negative, spec.dwell_s);
    }
    w.moveTo(park_mm, feed);
}

}  // namespace

std::vector<double> equallySpacedTargets(const RangeMm& travel_mm, int count, double margin_mm) {
    std::vector<double> targets;
    const double from = travel_mm.from_mm + margin_mm, to = travel_mm.to_mm - margin_mm;
    for (int i = 0; i < count; ++i)
        targets.push_back(count == 1 ? from : from + (to - from) * i / (count - 1));
    return targets;
}

Programme buildMovingStateProgramme(const MovingStateSpec& spec) {
    if (!(spec.feed_mm_min > 0) || !(spec.pass_feed_mm_min > 0))
        throw std::invalid_argument("moving state: feed must be positive");
    if (!(spec.range_mm.to_mm > spec.range_mm.from_mm))
        throw std::invalid_argument("moving state: range must have positive length");
    if (!(spec.warmup_s > 0) || spec.cooldown_s < 0 || !(spec.block_s > 0) ||
        !(spec.cooldown_interval_s > 0))
        throw std::invalid_argument("moving state: durations must be positive");
    if (spec.targets_mm.empty() || !std::is_sorted(spec.targets_mm.begin(), spec.targets_mm.end()))
        throw std::invalid_argument("moving state: targets must be given in ascending order");

    Programme p;
    const double park_mm = spec.range_mm.from_mm;
    ProgrammeWriter w(p, park_mm);
    int cycle = 0;
    interferometerPass(w, spec, cycle++, park_mm);

    const double stroke_s = (spec.range_mm.to_mm - spec.range_mm.from_mm) / spec.feed_mm_min * 60.0;
    while (w.time() < spec.warmup_s) {
        // Whole double strokes only, so every block ends back at the park position.
        const double block_end = std::min(w.time() + spec.block_s, spec.warmup_s);
        while (w.time() + 2 * stroke_s <= block_end) {
            w.moveTo(spec.range_mm.to_mm, spec.feed_mm_min);
            w.moveTo(spec.range_mm.from_mm, spec.feed_mm_min);
        }
        w.dwellUntil(block_end);
        interferometerPass(w, spec, cycle++, park_mm);
    }
    const double warm_end = w.time();
    for (double next = warm_end + spec.cooldown_interval_s;
         next <= warm_end + spec.cooldown_s + 1e-9; next += spec.cooldown_interval_s) {
        w.dwellUntil(next);
        interferometerPass(w, spec, cycle++, park_mm);
    }
    p.duration_s = w.time();
    return p;
}

AxisState axisStateAt(const std::vector<MotionSegment>& motion, double time_s) {
    if (motion.empty()) return {};
    auto it = std::upper_bound(motion.begin(), motion.end(), time_s,
                               [](double t, const MotionSegment& m) { return t < m.start_s; });
    if (it == motion.begin()) return {motion.front().from_mm, 0};
    const MotionSegment& m = *std::prev(it);
    if (time_s >= m.end_s) return {m.to_mm, 0};
    const double f = (time_s - m.start_s) / (m.end_s - m.start_s);
    return {m.from_mm + f * (m.to_mm - m.from_mm), m.isDwell() ? 0.0 : m.feed_mm_min};
}

}  // namespace driftlab::rig
