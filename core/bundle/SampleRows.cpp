#include "core/bundle/SampleRows.h"

#include <algorithm>
#include <cmath>

#include "core/bundle/ValueLimits.h"
#include "core/domain/MessageText.h"

namespace driftlab::bundle {

void mergeInto(HeldRow& held, const std::vector<double>& row, const CsvTable& csv,
               const std::vector<int>& columns, const QString& run) {
    for (std::size_t k = 0; k < row.size(); ++k) {
        if (std::isnan(row[k])) continue;
        if (std::isnan(held.values[k])) {
            held.values[k] = row[k];
        } else if (held.values[k] != row[k]) {
            csv.fail(columns[k],
                     QStringLiteral("column %1 reads %2 at %3 s of run %4, but %5 on line %6 "
                                    "at the same time: one instant cannot have two readings")
                         .arg(csv.columnName(columns[k]))
                         .arg(numberText(row[k]), numberText(held.time_s), quotedText(run),
                              numberText(held.values[k]))
                         .arg(held.line));
        }
    }
}

DisplacementExtents::DisplacementExtents(std::size_t runs,
                                         const std::vector<const Channel*>& columns)
    : m_columns(columns),
      m_extent(runs, std::vector<std::pair<std::size_t, double>>(columns.size())) {}

QStringList DisplacementExtents::warnings(const std::vector<Run>& runs) const {
    QStringList warnings;
    for (std::size_t r = 0; r < m_extent.size(); ++r)
        for (std::size_t k = 0; k < m_columns.size(); ++k) {
            const auto& [count, largest] = m_extent[r][k];
            if (count == 0) continue;  // not a drift probe, or not logged in this run
            if (const auto why = tinyMicrometres(
                    count, largest,
                    QStringLiteral("readings of %1").arg(quotedText(m_columns[k]->id))))
                warnings << QStringLiteral("run %1: %2").arg(quotedText(runs[r].id), *why);
        }
    return warnings;
}

double loggerClockOffset_s(const Run& run, double firstSample_s) {
    double first_s = firstSample_s;
    if (!run.motion.empty()) first_s = std::min(first_s, run.motion.front().start_s);
    if (!run.positioning.empty()) first_s = std::min(first_s, run.positioning.front().time_s);
    return first_s > kLoggerClockStart_s ? first_s : 0.0;
}

double onRunClock(double time_s, double offset_s) {
    return offset_s == 0 ? time_s : std::round((time_s - offset_s) * 1e6) / 1e6;
}

void moveOntoRunClock(Run& run, double offset_s) {
    for (MotionSegment& m : run.motion) {
        m.start_s = onRunClock(m.start_s, offset_s);
        m.end_s = onRunClock(m.end_s, offset_s);
    }
    for (PositioningMeasurement& p : run.positioning) p.time_s = onRunClock(p.time_s, offset_s);
}

}  // namespace driftlab::bundle
