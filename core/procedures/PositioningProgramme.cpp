// The ISO 230-2 positioning programme (declared in ProcedurePlan.h).
#include <stdexcept>

#include "core/procedures/ProcedurePlan.h"
#include "core/rig/ProgrammeWriter.h"

namespace driftlab::procedures {
namespace {

using rig::ProgrammeWriter;

/// All targets up, reversal past the last one, all targets down.
void linearCycle(ProgrammeWriter& w, const PositioningSpec& spec,
                 const std::vector<double>& targets, int cycle) {
    for (double x : targets) {
        w.moveTo(x, spec.feed_mm_min);
        w.measureAfterDwell(cycle, x, Direction::Positive, spec.dwell_s);
    }
    w.moveTo(targets.back() + spec.overrun_mm, spec.feed_mm_min);
    for (auto it = targets.rbegin(); it != targets.rend(); ++it) {
        w.moveTo(*it, spec.feed_mm_min);
        w.measureAfterDwell(cycle, *it, Direction::Negative, spec.dwell_s);
    }
}

/// Each target up, past it by the overrun, back down to it; then the next
/// target, which is above, so its positive approach comes from below too.
void pilgrimCycle(ProgrammeWriter& w, const PositioningSpec& spec,
                  const std::vector<double>& targets, int cycle) {
    for (double x : targets) {
        w.moveTo(x, spec.feed_mm_min);
        w.measureAfterDwell(cycle, x, Direction::Positive, spec.dwell_s);
        w.moveTo(x + spec.overrun_mm, spec.feed_mm_min);
        w.moveTo(x, spec.feed_mm_min);
        w.measureAfterDwell(cycle, x, Direction::Negative, spec.dwell_s);
    }
}

}  // namespace

rig::Programme buildPositioningProgramme(const PositioningSpec& spec) {
    if (!(spec.feed_mm_min > 0)) throw std::invalid_argument("positioning: feed must be positive");
    if (!(spec.overrun_mm > 0))
        throw std::invalid_argument("positioning: overrun must be positive");
    if (spec.cycles < 1 || !(spec.dwell_s >= 0))
        throw std::invalid_argument("positioning: need at least one cycle and a dwell >= 0");
    if (!(spec.span_mm.to_mm > spec.span_mm.from_mm))
        throw std::invalid_argument("positioning: span must have positive length");

    const std::vector<double> targets = positioningTargets(spec);
    rig::Programme p;
    // Start and end below the first target by the overrun: every cycle's first
    // positive approach then comes from below like all the others.
    const double park_mm = targets.front() - spec.overrun_mm;
    ProgrammeWriter w(p, park_mm);
    // Cycles 1 … n: every cycle is a measurement cycle (no cold reference pass
    // as in a moving-state run); core/iso/Iso230_2 only counts distinct numbers.
    for (int cycle = 1; cycle <= spec.cycles; ++cycle) {
        w.moveTo(park_mm, spec.feed_mm_min);
        if (spec.order == ApproachOrder::Linear)
            linearCycle(w, spec, targets, cycle);
        else
            pilgrimCycle(w, spec, targets, cycle);
    }
    w.moveTo(park_mm, spec.feed_mm_min);
    p.duration_s = w.time();
    return p;
}

}  // namespace driftlab::procedures
