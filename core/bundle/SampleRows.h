#pragma once
// How samples.csv's rows of a run are taken as other loggers write them: two
// rows at one time are one instant (two devices merged row by row, or a log
// written twice), and a run whose every file starts long after 0 was logged on
// a logger's clock; and a drift probe whose every reading is a few nm was
// logged in mm.

#include <QString>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "core/bundle/CsvTable.h"
#include "core/domain/Channel.h"
#include "core/domain/Run.h"

namespace driftlab::bundle {

/// A run's latest row of samples.csv, not yet stored.
struct HeldRow {
    double time_s = -std::numeric_limits<double>::infinity();
    int line = 0;
    std::vector<double> values;
    bool held = false;
};

/// The cells of a row at the held row's time fill its empty cells; a cell that
/// both give must agree: one instant has one reading (else csv.fail).
void mergeInto(HeldRow& held, const std::vector<double>& row, const CsvTable& csv,
               const std::vector<int>& columns, const QString& run);

/// Per run, how many readings each displacement column of samples.csv has and
/// the largest |value|: a drift probe logged in mm (tinyMicrometres).
class DisplacementExtents {
public:
    DisplacementExtents(std::size_t runs, const std::vector<const Channel*>& columns);
    /// One reading of channel column `k` (an index into `columns`, not null) in run `run`:
    /// inline, it is called for every cell of a channel.
    void add(std::size_t run, std::size_t k, double value) {
        if (m_columns[k]->quantity != Quantity::Displacement) return;
        auto& [count, largest] = m_extent[run][k];
        ++count;
        largest = std::max(largest, std::abs(value));
    }
    /// One warning per run and column that looks like mm.
    QStringList warnings(const std::vector<Run>& runs) const;

private:
    std::vector<const Channel*> m_columns;
    std::vector<std::vector<std::pair<std::size_t, double>>>
        m_extent;  ///< [run][k]: count, largest
};

/// A run whose first record in every file (sample, motion segment, positioning
/// reading) is later than this was logged on a logger's clock: time since the
/// logger was switched on, or since the campaign's first run. Below it, a late
/// first record is a logger that started late, and the models say so.
constexpr double kLoggerClockStart_s = 60;

/// What to subtract from the run's times: its earliest record when that is
/// later than kLoggerClockStart_s, else 0. `firstSample_s` is its first row of
/// samples.csv; motion and positioning are read before the samples.
double loggerClockOffset_s(const Run& run, double firstSample_s);

/// A time on the run's own clock, to the µs (no logger resolves finer), so
/// that "5002.1" less 5000 s is 2.1 s again and not 2.1000000000003638.
double onRunClock(double time_s, double offset_s);

/// Motion and positioning moved onto the run's own clock (the samples are
/// moved as they are read).
void moveOntoRunClock(Run& run, double offset_s);

}  // namespace driftlab::bundle
