#pragma once
// ISO 230-3 evaluation of thermal drift (docs/iso230-3.md):
//  - thermal distortion caused by moving linear axes: the drift of the
//    interferometer deviation at each target from the cold reference cycle 0;
//  - spindle and ETVE drift runs: the drift of each displacement probe from
//    its first sample, and, given the probe distance, the two tilts.
// ISO 230-3's own numbers are not public here: the stabilisation criterion
// (window W, tolerance D) is DriftLab's choice and always a setting.
// Every drift is in µm, every time in s since the run's start.

#include <QString>
#include <QStringList>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "core/domain/Campaign.h"
#include "core/domain/Run.h"

namespace driftlab::iso {

constexpr double kNotStabilised = std::numeric_limits<double>::quiet_NaN();

struct DriftSettings {
    /// W: length of the window over which the drift must stay within D.
    double window_s = 600;
    /// D: the drift must vary by less than this over every window of length W.
    double tolerance_um = 1;
    /// Targets closer than this are the same target (as in ISO 230-2).
    double target_tolerance_mm = 1e-6;
    /// Spindle runs: distance between the first and the second x (and y)
    /// probe along the test mandrel; without it no tilt is derived.
    std::optional<double> probe_distance_mm;

    /// True when the settings can be used; otherwise `why` says what is wrong.
    bool isValid(QString* why) const;
};

/// A drift time series and what is read from it. Stabilised at t_s: the
/// earliest sample time such that, for every sample time t_i ≥ t_s, the
/// drift (linear between samples) varies by less than D over [t_i, t_i + W]
/// (cut at the run's last sample), and the series goes on for at least W
/// after t_s. NaN when no sample time qualifies: "not stabilised within the run".
struct DriftSeries {
    std::vector<double> time_s;    ///< ascending
    std::vector<double> drift_um;  ///< relative to the reference (0 at the reference)
    double max_drift_um = 0;       ///< the drift of largest magnitude, with its sign
    double max_drift_time_s = 0;   ///< when it occurred (the first time, on a tie)
    double min_um = 0;             ///< smallest drift
    double max_um = 0;             ///< largest drift
    double range_um = 0;           ///< max_um − min_um
    double final_drift_um = 0;     ///< at the last sample
    double stabilised_time_s = kNotStabilised;

    bool stabilised() const { return !std::isnan(stabilised_time_s); }
};

/// Fills the summary fields of `series` from its time_s and drift_um.
void summarise(DriftSeries& series, const DriftSettings& settings);

/// The drift at one target in one direction: deviation(cycle c) − deviation(cycle 0).
struct TargetDrift {
    double target_mm = 0;
    Direction direction = Direction::Positive;
    std::vector<int> cycles;  ///< the cycle of each sample of `drift`
    DriftSeries drift;
};

/// Moving linear axis: every target and direction, and the axis figures.
struct AxisDriftEvaluation {
    QString error;  ///< empty on success; names the run
    QString run_id;
    DriftSettings settings;
    /// Ascending target_mm, '+' before '-' at a target; directions never mixed.
    std::vector<TargetDrift> targets;
    int cycles = 0;           ///< distinct cycle numbers, the reference included
    double zero_mm = 0;       ///< the first target (the axis "zero")
    double far_end_mm = 0;    ///< the last target
    int max_index = -1;       ///< the target and direction of the largest |drift|
    double max_drift_um = 0;  ///< = targets[max_index].drift.max_drift_um
    /// The latest stabilisation over all targets and directions; NaN when one is not stabilised.
    double stabilised_time_s = kNotStabilised;
    QStringList warnings;

    bool ok() const { return error.isEmpty(); }
    /// The drift at a target (within the target tolerance) and direction, or nullptr.
    const TargetDrift* find(double target_mm, Direction direction) const;
};

/// Evaluates a run's positioning readings (cycle 0 is the cold reference).
/// Never throws: a failure is AxisDriftEvaluation::error.
AxisDriftEvaluation evaluateAxisDrift(const Run& run, const DriftSettings& settings = {});

/// One displacement probe (a channel of quantity displacement).
struct ProbeDrift {
    QString channel_id;
    ChannelRole role = ChannelRole::Drift;
    double reference_um = 0;  ///< the probe's first sample, the reference of its drift
    DriftSeries drift;
};

/// A tilt from two probes at probe_distance_mm: the difference of their drifts
/// (second probe − first probe) as a series, and the same as an angle.
struct TiltDrift {
    QString name;       ///< "A" (about x, from the y probes) or "B" (about y, from the x probes)
    QString from, to;   ///< channel ids: tilt = (drift(to) − drift(from)) / distance
    DriftSeries drift;  ///< the differential drift in µm
    double max_tilt_urad = 0;  ///< max_drift_um / distance, in µrad (µm/m)
    double range_urad = 0;     ///< range_um / distance
};

/// Spindle or ETVE run: each probe, the tilts where defined, and the run figures.
struct ProbeDriftEvaluation {
    QString error;  ///< empty on success; names the run
    QString run_id;
    RunKind kind = RunKind::Spindle;
    DriftSettings settings;
    std::vector<ProbeDrift> probes;  ///< in the campaign's channel order
    std::vector<TiltDrift> tilts;    ///< empty without probe_distance_mm
    /// The latest stabilisation over the probes; NaN when one is not stabilised.
    double stabilised_time_s = kNotStabilised;
    QStringList notes;     ///< what was not derived and why
    QStringList warnings;  ///< unusual but not wrong

    bool ok() const { return error.isEmpty(); }
};

/// Evaluates the displacement channels of `run` found by quantity and role.
/// Never throws: a failure is ProbeDriftEvaluation::error.
ProbeDriftEvaluation evaluateProbeDrift(const Campaign& campaign, const Run& run,
                                        const DriftSettings& settings = {});

}  // namespace driftlab::iso
