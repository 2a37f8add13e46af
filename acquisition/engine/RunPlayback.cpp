#include "acquisition/engine/RunPlayback.h"

namespace driftlab::engine {

RunPlayback::RunPlayback(procedures::PlannedRun r, std::size_t i, std::size_t n, db::RunLogger& l,
                         const std::vector<QString>& c)
    : run(std::move(r)), index(i), count(n), logger(l), columns(c) {}

void RunPlayback::resumeFrom(const db::LoggedRunState& state, bool realTime) {
    // A little slack: times are logged as computed, and compared as logged.
    m_skipSamples_s = state.last_sample_s.value_or(-1) + 1e-9;
    m_skipReadings_s = state.last_reading_s.value_or(-1) + 1e-9;
    m_skipMotion = std::size_t(state.motion_segments);
    if (realTime) time_s = state.end_s();
}

void RunPlayback::log(const rig::RunOutput& out, const RowObserver& observer,
                      const ReadingObserver& readingObserver) {
    const std::size_t width = columns.size();
    for (std::size_t r = 0; r < out.time_s.size(); ++r) {
        if (out.time_s[r] <= m_skipSamples_s) continue;
        const double* row = out.rows.data() + r * width;
        logger.appendRow(out.time_s[r], row);
        if (observer) observer(out.time_s[r], row, width);
    }
    for (const PositioningMeasurement& p : out.readings)
        if (p.time_s > m_skipReadings_s) {
            logger.appendReading(p);
            if (readingObserver) readingObserver(p);
        }
}

void RunPlayback::logMotionUntil(double until_s) {
    const auto& motion = run.programme.motion;
    for (; m_nextMotion < motion.size() && motion[m_nextMotion].end_s <= until_s + 1e-9;
         ++m_nextMotion)
        if (m_nextMotion >= m_skipMotion) logger.appendMotion(motion[m_nextMotion]);
}

std::optional<QString> RunPlayback::checkStabilisation(const rig::RunOutput& out) {
    if (!run.warmup || m_stabilised) return std::nullopt;
    const int perPass = 2 * int(run.warmup->targets_mm.size());
    for (const PositioningMeasurement& p : out.readings) {
        m_readings.push_back(p);
        // Cycle 0 is the cold reference; warm-up passes end by the planned warm-up.
        if (p.cycle < 1 || ++m_perCycle[p.cycle] != perPass || p.time_s > run.warmup->warmup_s)
            continue;
        const auto change_um = procedures::passChange_um(m_readings);
        if (!change_um || *change_um > run.stabilisation_um) continue;
        run = procedures::replanWarmupEnd(run, p.time_s);
        m_stabilised = true;
        return QStringLiteral(
                   "stabilised after warm-up pass %1 at %2 s: the largest change "
                   "from the pass before is %3 µm (criterion %4 µm); cooling down")
            .arg(p.cycle)
            .arg(p.time_s)
            .arg(*change_um, 0, 'f', 2)
            .arg(run.stabilisation_um);
    }
    return std::nullopt;
}

}  // namespace driftlab::engine
