#pragma once
// What the procedure engine drives: a rig that gives, for each planned run,
// a source of sample rows and interferometer readings (RunSource). The
// simulated rig computes them from the physics at any speed-up; a device rig
// reads the temperature module, the controller and the interferometer in
// real time. Both implement the same two small interfaces.

#include <QString>
#include <memory>
#include <vector>

#include "core/domain/Campaign.h"
#include "core/procedures/ProcedurePlan.h"
#include "core/rig/SimulatedAxisRun.h"

namespace driftlab::engine {

/// Something a device or the rig reports for the run's event log.
struct SourceEvent {
    QString level;  ///< info, warning, error
    QString source;
    QString message;
};

class RunSource {
public:
    virtual ~RunSource() = default;
    /// Advances the run to `until_s` and appends what fell due to `out`.
    virtual void advanceTo(double until_s, rig::RunOutput& out) = 0;
    virtual double time_s() const = 0;
    virtual bool finished() const = 0;
    /// Replaces the rest of the programme (ISO 230-3: warm-up ended at
    /// stabilisation). A real machine runs its own NC programme: its source
    /// only records that the operator must end the warm-up.
    virtual void replan(const procedures::PlannedRun& run) = 0;
    /// Gaps, reconnects and errors since the last call.
    virtual std::vector<SourceEvent> takeEvents() { return {}; }
    /// True while a device of the run is lost (no data).
    virtual bool deviceLost() const { return false; }
    /// Why the run cannot go on (a device that never answered within its
    /// connect timeout), or empty.
    virtual QString failure() const { return {}; }
};

class TestRig {
public:
    virtual ~TestRig() = default;
    virtual QString describe() const = 0;
    /// Real-time rigs are paced by the clock; a simulated one by the speed-up.
    virtual bool realTime() const = 0;
    /// The campaign the runs are logged into, without runs.
    virtual Campaign campaignHeader(const std::vector<procedures::PlannedRun>& runs) const = 0;
    /// The source of planned run `index` of the procedure; nullptr with `error`.
    virtual std::unique_ptr<RunSource> open(const procedures::PlannedRun& run, std::size_t index,
                                            const std::vector<QString>& columns,
                                            QString* error) = 0;
};

}  // namespace driftlab::engine
