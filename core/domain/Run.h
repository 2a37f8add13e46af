#pragma once
// A run of a campaign and the data logged during it. Units are in the names.

#include <QJsonObject>
#include <QString>
#include <cmath>
#include <optional>
#include <vector>

namespace driftlab {

enum class RunKind {
    Moving,       ///< feed axis moving state: warm-up, then cool-down
    Spindle,      ///< ISO 230-3 spindle test: speed programme, drift probes
    Etve,         ///< environmental temperature variation
    Positioning,  ///< ISO 230-2 positioning run
};
QString toString(RunKind kind);
std::optional<RunKind> runKindFromString(const QString& text);
/// Feed-axis runs carry their thermal error in positioning.csv and need the screw.
bool isFeedAxisRun(RunKind kind);

struct RangeMm {
    double from_mm = 0;
    double to_mm = 0;
    bool operator==(const RangeMm&) const = default;
};

/// The nut moves linearly from `from_mm` to `to_mm` between `start_s` and `end_s`.
struct MotionSegment {
    double start_s = 0;
    double end_s = 0;
    double from_mm = 0;
    double to_mm = 0;
    double feed_mm_min = 0;  ///< commanded feed, signed as logged
    bool isDwell() const { return from_mm == to_mm; }
    bool operator==(const MotionSegment&) const = default;
};

enum class Direction { Positive, Negative };
/// A direction of approach as DriftLab writes it ('+' the positive approach ↑,
/// '-' the negative ↓) or as other software does: the arrows, up/down,
/// pos/neg, positive/negative in any case, +1/-1, a typographic minus.
/// Surrounding blanks are allowed; nullopt for anything else.
std::optional<Direction> directionFromText(const QString& text);

/// One interferometer reading. deviation_um = actual - target (ISO 230-2 sign).
struct PositioningMeasurement {
    double time_s = 0;
    int cycle = 0;  ///< cycle 0 at time 0 is the cold reference
    double target_mm = 0;
    Direction direction = Direction::Positive;
    double deviation_um = 0;
    bool operator==(const PositioningMeasurement&) const = default;
};

/// Wide sensor time series of one run: values[column][row], NaN = missing sample.
/// The columns are the campaign's samples.csv columns (channels and axis columns).
struct SampleSeries {
    std::vector<double> time_s;
    std::vector<QString> columns;
    std::vector<std::vector<double>> values;

    std::size_t rowCount() const { return time_s.size(); }
    /// Index of a column, or -1.
    int columnIndex(const QString& column) const;
    /// Number of present (non-missing) values over all columns.
    std::size_t presentValueCount() const;
    bool operator==(const SampleSeries& other) const;
};

struct Run {
    QString id;
    RunKind kind = RunKind::Moving;
    std::optional<double> feed_mm_min;
    std::optional<RangeMm> range_mm;
    QString description;
    QJsonObject extra;  ///< keys this version does not know, kept for lossless export

    SampleSeries samples;
    std::vector<MotionSegment> motion;
    std::vector<PositioningMeasurement> positioning;

    bool operator==(const Run&) const = default;
};

}  // namespace driftlab
