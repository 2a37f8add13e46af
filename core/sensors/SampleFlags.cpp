#include "core/sensors/SampleFlags.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace driftlab::sensors {

std::optional<SensorFault> sensorFaultFromString(const QString& text) {
    for (SensorFault fault : kAllSensorFaults)
        if (toString(fault) == text) return fault;
    return std::nullopt;
}

std::vector<FlaggedRange> flaggedRanges(const std::map<QString, ChannelHealth>& checked) {
    std::vector<FlaggedRange> ranges;
    for (const auto& [channel, health] : checked)
        for (const FaultFinding& finding : health.summary.findings)
            for (const TimeRange& r : finding.ranges)
                ranges.push_back({channel, finding.fault, r.from_s, r.to_s});
    return ranges;
}

std::size_t maskFlaggedSamples(Run& run, const std::vector<FlaggedRange>& ranges,
                               QStringList* maskedChannels) {
    SampleSeries& s = run.samples;
    std::size_t masked = 0;
    for (const FlaggedRange& range : ranges) {
        const int c = s.columnIndex(range.channel);
        if (c < 0 || std::size_t(c) >= s.values.size()) continue;
        std::vector<double>& column = s.values[std::size_t(c)];
        // Sample times increase within a run: the range is one slice.
        const auto first = std::lower_bound(s.time_s.begin(), s.time_s.end(), range.from_s);
        const auto end = std::upper_bound(first, s.time_s.end(), range.to_s);
        std::size_t here = 0;
        for (auto i = std::size_t(first - s.time_s.begin());
             i < std::size_t(end - s.time_s.begin()) && i < column.size(); ++i) {
            if (std::isnan(column[i])) continue;
            column[i] = std::numeric_limits<double>::quiet_NaN();
            ++here;
        }
        masked += here;
        if (here && maskedChannels && !maskedChannels->contains(range.channel))
            *maskedChannels << range.channel;
    }
    return masked;
}

}  // namespace driftlab::sensors
