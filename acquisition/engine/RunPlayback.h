#pragma once
// One run as the engine plays it: what of the rig's output is logged (a
// resumed run skips what its log already holds), the motion segments as they
// are completed, and the ISO 230-3 stabilisation check after every pass.

#include <map>
#include <optional>
#include <vector>

#include "acquisition/engine/ProcedureEngine.h"
#include "db/RunLogger.h"

namespace driftlab::engine {

struct RunPlayback {
    RunPlayback(procedures::PlannedRun run, std::size_t index, std::size_t count,
                db::RunLogger& logger, const std::vector<QString>& columns);

    procedures::PlannedRun run;
    std::size_t index, count;
    db::RunLogger& logger;
    const std::vector<QString>& columns;
    double time_s = 0;  ///< run time reached

    /// Continue a run whose log ends at `state`: a simulated rig replays up
    /// to there without logging; a real one goes on from there (the gap is
    /// the time it was down).
    void resumeFrom(const db::LoggedRunState& state, bool realTime);
    /// A resumed run not yet past the end of its log (what a simulated rig
    /// reports meanwhile is logged already).
    bool replaying() const { return time_s <= m_skipSamples_s; }
    /// Logs what of `out` the log does not hold yet and tells the observers.
    void log(const rig::RunOutput& out, const RowObserver& observer,
             const ReadingObserver& readingObserver = {});
    /// Logs the motion segments that end by `until_s`.
    void logMotionUntil(double until_s);
    /// ISO 230-3 axis runs: after a completed warm-up pass whose change from
    /// the pass before is within the criterion, replans the run to cool down
    /// and returns what happened (for the log); nullopt otherwise.
    std::optional<QString> checkStabilisation(const rig::RunOutput& out);

private:
    double m_skipSamples_s = -1, m_skipReadings_s = -1;
    std::size_t m_skipMotion = 0, m_nextMotion = 0;
    std::vector<PositioningMeasurement> m_readings;
    std::map<int, int> m_perCycle;
    bool m_stabilised = false;
};

}  // namespace driftlab::engine
