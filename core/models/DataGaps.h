#pragma once
// Holes in a logged channel: a module that did not answer, a sensor whose
// flagged stretch was masked. A hole is judged by the channel's own course on
// either side of it, not by one fixed limit: a channel that changes slowly
// against the hole (a room thermometer over a three-minute outage) is bridged
// by interpolation; across a hole the channel's course does not let DriftLab
// bridge, the observations inside it are left out of fitting and scoring and
// the rest of the run is used. Every hole is reported, never silently taken.

#include <QString>
#include <QStringList>
#include <cstddef>
#include <limits>
#include <vector>

namespace driftlab::models {

struct Signal;
struct RunData;

/// A stretch without samples longer than this many of the channel's own
/// intervals is a hole; one or two missing cells are not.
inline constexpr double kHoleIntervals = 3;

/// One hole of one channel in one run, as reported (`gaps` in the JSON).
struct DataGap {
    QString run_id;
    QString channel;          ///< channel id or axis column
    QString unit;             ///< of the two figures below
    double from_s = 0;        ///< the last sample before the hole
    double to_s = 0;          ///< the first sample after it, or the run's end
    bool to_run_end = false;  ///< no sample after it
    bool bridged = false;
    /// How far a straight bridge may be from the channel's course (from the
    /// lines through its samples on either side), and what is allowed: three
    /// times the channel's noise, at least its resolution. NaN for a hole at
    /// the run's end, which has no second side.
    double bridge_error = std::numeric_limits<double>::quiet_NaN();
    double tolerance = std::numeric_limits<double>::quiet_NaN();
    /// Observations inside the hole, left out of fitting and scoring (0 when
    /// bridged).
    std::size_t observations_left_out = 0;
};

/// Finds and judges the holes of `signal` (time ascending, present samples
/// only) up to `runEnd_s`, records them in signal.holes and appends one
/// DataGap per hole to `gaps`. A `stepped` signal (the axis columns and the
/// spindle's speed, which change in steps, not smoothly) is bridged only
/// where it runs straight through the hole: the same speed on both sides.
void judgeHoles(Signal& signal, const QString& runId, double runEnd_s, const QString& unit,
                bool stepped, std::vector<DataGap>& gaps);

/// Drops the run's observations that fall inside a hole left out, counting
/// them in the run's gaps; throws ModelError when no observation is left.
void leaveOutHoles(RunData& run);

/// The gaps of every run, in run order.
std::vector<DataGap> gapsOf(const std::vector<RunData>& runs);

/// One line per hole left out, and one line summing up the bridged ones
/// (empty without gaps): what `fit`, `diagnose` and the GUI say of the log.
QStringList gapLines(const std::vector<DataGap>& gaps);

}  // namespace driftlab::models
