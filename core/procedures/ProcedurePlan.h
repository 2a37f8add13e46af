#pragma once
// A procedure planned into runs: for each run its kind, its motion and the
// interferometer readings it asks for (rig::Programme), which the engine
// plays on a rig. The ISO 230-3 axis run is planned to its longest warm-up;
// the engine ends the warm-up early when the stabilisation criterion holds
// (replanWarmupEnd), which keeps every motion before it unchanged.

#include <QString>
#include <optional>
#include <vector>

#include "core/procedures/Procedure.h"
#include "core/rig/MovingStateProgramme.h"
#include "core/rig/SpindleTestSimulator.h"

namespace driftlab::procedures {

struct PlannedRun {
    QString id;
    RunKind kind = RunKind::Moving;
    std::optional<double> feed_mm_min;
    std::optional<RangeMm> range_mm;
    QString description;
    /// Motion and readings of a feed-axis run (empty for spindle and ETVE).
    rig::Programme programme;
    /// Set for the ISO 230-3 axis run: the spec the programme was built from,
    /// and the stabilisation criterion the engine checks after every pass.
    std::optional<rig::MovingStateSpec> warmup;
    double stabilisation_um = 0;
    /// Set for spindle and ETVE runs: the speed programme (all stops for ETVE).
    std::optional<rig::SpindleTestSpec> spindle;
    double duration_s = 0;
};

/// The runs of a procedure, in the order they are run. Throws
/// std::invalid_argument when the procedure cannot be planned (a range
/// outside the travel); parseProcedure() has checked everything else.
std::vector<PlannedRun> planRuns(const Procedure& procedure);

/// ISO 230-2 programme: `cycles` bidirectional cycles over positioningTargets(),
/// linear (all targets up, then all down) or pilgrim (each target approached
/// up then down before the next); every approach of a direction comes from
/// the same side (the overrun), a reading after `dwell_s` at each target.
rig::Programme buildPositioningProgramme(const PositioningSpec& spec);

/// The ISO 230-3 run with its warm-up ended at `warmupEnd_s` (the end of the
/// pass at which the criterion held): the same motion up to then, then the
/// cool-down. `run.warmup` must be set.
PlannedRun replanWarmupEnd(const PlannedRun& run, double warmupEnd_s);

/// Largest change of the deviation between the last two passes, over the
/// targets and both directions, µm; nullopt before the second warm-up pass.
std::optional<double> passChange_um(const std::vector<PositioningMeasurement>& readings);

}  // namespace driftlab::procedures
