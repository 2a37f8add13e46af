#pragma once
// The data a thermal-error model sees, built from a campaign: per run, the
// thermal error observations, the temperature rise of every temperature channel
// and the axis signals. Every model reads the same data, so every model is
// scored against the same thermal error.

#include <Eigen/Core>
#include <QString>
#include <QStringList>
#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

#include "core/domain/Campaign.h"
#include "core/models/DataGaps.h"
#include "core/models/DriveTorqueModel.h"

namespace driftlab::models {

struct DatasetOptions {
    /// A displacement channel to predict (`--target`); empty: the positioning
    /// error of feed-axis runs.
    QString target_channel;
    /// A temperature rise is taken from the median of the samples in this first
    /// window of the channel (robust to a spike in the first sample), s.
    double reference_window_s = 60;
};

/// One thermal error observation.
/// Positioning target: error_um = deviation_um − deviation_um of cycle 0 at the
/// same target and direction, which removes the cold geometric error and the
/// backlash. Drift target: the channel's sample minus the median of its samples
/// in the first reference_window_s, with position_mm 0 and cycle −1.
struct ErrorObservation {
    double time_s = 0;
    double position_mm = 0;
    Direction direction = Direction::Positive;
    int cycle = 0;
    double error_um = 0;
};

/// Where and when a model is evaluated: time in the run and axis position.
struct PredictionPoint {
    double time_s = 0;
    double position_mm = 0;
};

/// A hole in a signal (see DataGaps.h): from its last sample before to its
/// first after (or the run's end), bridged or left out.
struct SignalHole {
    double from_s = 0, to_s = 0;
    bool bridged = false;
    bool to_run_end = false;  ///< no sample after it: it holds the run's end too
    bool holds(double time_s) const { return time_s > from_s && (time_s < to_s || to_run_end); }
};

/// A sampled signal with its missing samples removed, time ascending.
struct Signal {
    QString name;  ///< channel id or axis column
    std::vector<double> time_s;
    std::vector<double> value;
    /// The median interval between its samples: a logger's own rhythm, which
    /// a hole is measured against (kHoleIntervals of it); 0 when unknown. A
    /// thermometer read every 5 min is no outage.
    double sampling_s = 0;
    /// Its holes, in time order (judgeHoles).
    std::vector<SignalHole> holes;
    bool empty() const { return time_s.empty(); }
    /// The hole left out that holds `time_s` (strictly inside), or nullptr.
    const SignalHole* leftOutHoleAt(double time_s) const {
        for (const SignalHole& h : holes)
            if (!h.bridged && h.holds(time_s)) return &h;
        return nullptr;
    }
};

/// The rise ΔT = T − T(run start) of one temperature channel over one run.
struct TemperatureRise {
    QString channel_id;
    ChannelRole role = ChannelRole::Other;
    std::optional<double> position_mm;
    double reference_C = std::numeric_limits<double>::quiet_NaN();
    Signal rise_K;
    /// Why the channel cannot be used in this run (no samples, no reference at
    /// the run's start); empty when usable.
    QString unusable;
};

struct RunData {
    QString run_id;
    RunKind kind = RunKind::Moving;
    QString target_channel;      ///< empty: positioning error
    std::optional<Screw> screw;  ///< the campaign's screw
    std::optional<double> nut_length_mm;
    std::optional<Interferometer> interferometer;
    double reference_window_s = 60;  ///< from DatasetOptions
    /// The holes of its channels, bridged or left out (DataGaps.h).
    std::vector<DataGap> gaps;
    std::vector<ErrorObservation> observations;
    /// Every temperature channel of the campaign, in declaration order.
    std::vector<TemperatureRise> temperatures;
    Signal position_mm, feed_mm_min, torque_Nm;  ///< axis columns; empty when not logged
    Signal spindle_speed_rpm;  ///< the first speed channel; no name when the campaign has none
    std::vector<MotionSegment> motion;
    /// The drive identified over all the campaign's runs when the torque is
    /// logged as instantaneous samples (see DriveTorque.h); none for an RMS log.
    std::optional<DriveTorqueModel> drive_torque;

    /// The screw's fixed end, zero of the position gain (0 without a screw).
    double fixedEnd_mm() const { return screw ? screw->fixed_end_mm : 0.0; }
    std::optional<double> lead_mm() const {
        return screw ? std::optional<double>(screw->lead_mm) : std::nullopt;
    }
    /// A positioning error depends on the axis position; a drift channel does not.
    bool positionDependent() const { return target_channel.isEmpty(); }
    std::vector<PredictionPoint> observationPoints() const;
    Eigen::VectorXd observedErrors() const;
};

struct DatasetResult {
    std::vector<RunData> runs;  ///< in the order asked for
    QString error;              ///< names the run and what is wrong; empty on success
    bool ok() const { return error.isEmpty(); }
};

/// Builds the model data of the runs. Fails (never throws) on a run that is not
/// in the campaign, a feed-axis run without positioning data or without cycle 0,
/// a non-finite measurement, a spindle/ETVE run without a target channel, or a
/// target that is not a displacement channel.
DatasetResult buildDataset(const Campaign& campaign, const QStringList& runIds,
                           const DatasetOptions& options = {});

}  // namespace driftlab::models
