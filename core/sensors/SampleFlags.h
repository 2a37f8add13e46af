#pragma once
// Flagged samples as stored (db/SampleFlagStore.h, table sample_flag) and used
// by the models: a run's findings as time ranges per channel and kind, and
// leaving those samples out of a run (NaN, a missing sample to every model).
// A range holds consecutive flagged samples of one kind (SensorHealth.h), so
// masking [from_s, to_s] of its channel masks exactly those samples.

#include <QString>
#include <QStringList>
#include <map>
#include <optional>
#include <vector>

#include "core/domain/Run.h"
#include "core/sensors/SensorHealth.h"

namespace driftlab::sensors {

struct FlaggedRange {
    QString channel;
    SensorFault fault = SensorFault::OutOfRange;
    double from_s = 0;  ///< first flagged sample
    double to_s = 0;    ///< last flagged sample (inclusive)
    bool operator==(const FlaggedRange&) const = default;
};

/// The kind whose stable id (toString) is `text`.
std::optional<SensorFault> sensorFaultFromString(const QString& text);

/// Every finding of checkRun's result as ranges, by channel then kind.
std::vector<FlaggedRange> flaggedRanges(const std::map<QString, ChannelHealth>& checked);

/// Sets the present samples of `run` inside `ranges` to NaN; returns how many
/// it masked (a sample in two ranges counts once). Ranges of a channel the run
/// has no column for mask nothing. `maskedChannels`, when given, gets the
/// channels that lost a sample (each once).
std::size_t maskFlaggedSamples(Run& run, const std::vector<FlaggedRange>& ranges,
                               QStringList* maskedChannels = nullptr);

}  // namespace driftlab::sensors
