#include "core/models/ThermalErrorData.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/domain/Median.h"
#include "core/models/DriveTorque.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {
namespace {

QString directionText(Direction d) {
    return d == Direction::Positive ? QStringLiteral("+") : QStringLiteral("-");
}

/// Checks what the bundle reader guarantees, for campaigns built in code.
void checkSampleTable(const Run& run) {
    const SampleSeries& s = run.samples;
    for (std::size_t i = 0; i < s.time_s.size(); ++i) {
        if (!std::isfinite(s.time_s[i]))
            throw ModelError(QStringLiteral("run '%1': sample time %2 is NaN or infinite")
                                 .arg(run.id)
                                 .arg(i + 1));
        if (i > 0 && s.time_s[i] <= s.time_s[i - 1])
            throw ModelError(
                QStringLiteral("run '%1': sample time goes backwards or repeats "
                               "(%2 s after %3 s)")
                    .arg(run.id, messageNumber(s.time_s[i]), messageNumber(s.time_s[i - 1])));
    }
    if (s.values.size() != s.columns.size())
        throw ModelError(QStringLiteral("run '%1': %2 sample columns but %3 value columns")
                             .arg(run.id)
                             .arg(s.columns.size())
                             .arg(s.values.size()));
    for (std::size_t c = 0; c < s.columns.size(); ++c)
        if (s.values[c].size() != s.time_s.size())
            throw ModelError(
                QStringLiteral("run '%1': column '%2' has %3 values for %4 sample times")
                    .arg(run.id, s.columns[c])
                    .arg(s.values[c].size())
                    .arg(s.time_s.size()));
}

/// The median of a signal's samples in its first `window_s`: the zero of a
/// rise or a drift, robust to a spike in the first sample.
double firstWindowMedian(const Signal& s, double window_s) {
    std::vector<double> window;
    for (std::size_t i = 0; i < s.time_s.size() && s.time_s[i] <= s.time_s.front() + window_s; ++i)
        window.push_back(s.value[i]);
    return median(window);
}

/// The present samples of a column (NaN marks a missing sample).
Signal presentSamples(const Run& run, const QString& column) {
    Signal signal;
    signal.name = column;
    const int c = run.samples.columnIndex(column);
    if (c < 0) return signal;
    const std::vector<double>& values = run.samples.values[std::size_t(c)];
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (std::isnan(values[i])) continue;
        if (!std::isfinite(values[i]))
            throw ModelError(
                QStringLiteral("run '%1', %2: infinite value at t = %3 s")
                    .arg(run.id, describeSignal(signal), messageNumber(run.samples.time_s[i])));
        signal.time_s.push_back(run.samples.time_s[i]);
        signal.value.push_back(values[i]);
    }
    if (signal.time_s.size() > 1) {
        std::vector<double> intervals(signal.time_s.size() - 1);
        for (std::size_t i = 1; i < signal.time_s.size(); ++i)
            intervals[i - 1] = signal.time_s[i] - signal.time_s[i - 1];
        signal.sampling_s = median(std::move(intervals));
    }
    return signal;
}

TemperatureRise temperatureRise(const Run& run, const Channel& channel,
                                const DatasetOptions& options) {
    TemperatureRise rise;
    rise.channel_id = channel.id;
    rise.role = channel.role;
    rise.position_mm = channel.position_mm;
    rise.rise_K = presentSamples(run, channel.id);
    Signal& s = rise.rise_K;
    const QString where = QStringLiteral("run '%1', %2").arg(run.id, describeSignal(s));
    if (s.empty()) {
        rise.unusable = where + QStringLiteral(": no samples in this run");
        return rise;
    }
    // The reference is the median of the first window: a first sample later
    // than two windows (or than a hole of the channel's own rhythm) is no
    // reading of the run's start.
    const double latest_s = std::max(2 * options.reference_window_s, kHoleIntervals * s.sampling_s);
    if (s.time_s.front() > latest_s) {
        rise.unusable = where + QStringLiteral(
                                    ": first sample at %1 s, too late for a reference "
                                    "at the run's start (limit %2 s)")
                                    .arg(messageNumber(s.time_s.front()), messageNumber(latest_s));
        return rise;
    }
    rise.reference_C = firstWindowMedian(s, options.reference_window_s);
    for (double& v : s.value) v -= rise.reference_C;
    return rise;
}

std::vector<ErrorObservation> positioningErrors(const Run& run) {
    if (run.positioning.empty())
        throw ModelError(QStringLiteral("run '%1' has no positioning measurements "
                                        "(positioning.csv): its thermal error is unknown")
                             .arg(run.id));
    // The cold reading of each target and direction (several are averaged).
    struct Reference {
        double target_mm;
        Direction direction;
        double sum_um = 0;
        int count = 0;
    };
    std::vector<Reference> references;
    auto findReference = [&](const PositioningMeasurement& m) -> Reference* {
        for (Reference& r : references)
            if (r.direction == m.direction && std::abs(r.target_mm - m.target_mm) <= 1e-6)
                return &r;
        return nullptr;
    };
    for (std::size_t i = 0; i < run.positioning.size(); ++i) {
        const PositioningMeasurement& m = run.positioning[i];
        if (!std::isfinite(m.time_s) || !std::isfinite(m.target_mm) ||
            !std::isfinite(m.deviation_um))
            throw ModelError(QStringLiteral("run '%1': positioning measurement %2 (cycle %3) has a "
                                            "NaN or infinite time, target or deviation")
                                 .arg(run.id)
                                 .arg(i + 1)
                                 .arg(m.cycle));
        if (m.cycle < 0)
            throw ModelError(QStringLiteral("run '%1': positioning measurement %2 has a negative "
                                            "cycle %3")
                                 .arg(run.id)
                                 .arg(i + 1)
                                 .arg(m.cycle));
        if (m.cycle != 0) continue;
        Reference* r = findReference(m);
        if (!r) r = &references.emplace_back(Reference{m.target_mm, m.direction});
        r->sum_um += m.deviation_um;
        ++r->count;
    }
    if (references.empty())
        throw ModelError(QStringLiteral("run '%1' has no cycle 0 (the cold reference) in its "
                                        "positioning measurements")
                             .arg(run.id));
    std::vector<ErrorObservation> observations;
    for (const PositioningMeasurement& m : run.positioning) {
        if (m.cycle == 0) continue;
        const Reference* r = findReference(m);
        if (!r)
            throw ModelError(QStringLiteral("run '%1': cycle %2 measures target %3 mm (%4) but "
                                            "cycle 0 does not, so it has no cold reference")
                                 .arg(run.id)
                                 .arg(m.cycle)
                                 .arg(messageNumber(m.target_mm), directionText(m.direction)));
        observations.push_back(
            {m.time_s, m.target_mm, m.direction, m.cycle, m.deviation_um - r->sum_um / r->count});
    }
    if (observations.empty())
        throw ModelError(QStringLiteral("run '%1' has only the cold reference cycle 0: no "
                                        "thermal error to model")
                             .arg(run.id));
    return observations;
}

std::vector<ErrorObservation> driftErrors(const Run& run, const QString& channel,
                                          double referenceWindow_s) {
    const Signal s = presentSamples(run, channel);
    if (s.time_s.size() < 2)
        throw ModelError(QStringLiteral("run '%1' has no samples of the target channel '%2'")
                             .arg(run.id, channel));
    // The drift's zero is the median of the first window, as a temperature
    // rise's is: a single first reading carries the probe's whole noise into
    // every later error of the run, as an offset no model can predict.
    const double reference_um = firstWindowMedian(s, referenceWindow_s);
    std::vector<ErrorObservation> observations;
    for (std::size_t i = 0; i < s.time_s.size(); ++i)
        observations.push_back(
            {s.time_s[i], 0.0, Direction::Positive, -1, s.value[i] - reference_um});
    return observations;
}

QStringList displacementChannels(const Campaign& campaign) {
    QStringList ids;
    for (const Channel& c : campaign.channels)
        if (c.quantity == Quantity::Displacement) ids << c.id;
    return ids;
}

void checkTarget(const Campaign& campaign, const QString& target) {
    if (target.isEmpty()) return;
    const Channel* channel = campaign.findChannel(target);
    if (!channel)
        throw ModelError(
            QStringLiteral("target channel '%1' is not a channel of this campaign").arg(target));
    if (channel->quantity != Quantity::Displacement)
        throw ModelError(QStringLiteral("target channel '%1' is a %2 channel; a target must be a "
                                        "displacement channel (%3)")
                             .arg(target, toString(channel->quantity),
                                  displacementChannels(campaign).join(QStringLiteral(", "))));
}

/// The holes of every input a model may read: the usable temperature
/// channels, the axis columns and the spindle's speed.
void judgeRunHoles(RunData& data, double runEnd_s) {
    for (TemperatureRise& t : data.temperatures)
        if (t.unusable.isEmpty())
            judgeHoles(t.rise_K, data.run_id, runEnd_s, QStringLiteral("K"), false, data.gaps);
    const std::pair<Signal*, QString> columns[] = {
        {&data.position_mm, QStringLiteral("mm")},
        {&data.feed_mm_min, QStringLiteral("mm/min")},
        {&data.torque_Nm, QStringLiteral("N·m")},
        {&data.spindle_speed_rpm, QStringLiteral("rpm")}};
    for (const auto& [signal, unit] : columns)
        judgeHoles(*signal, data.run_id, runEnd_s, unit, true, data.gaps);
}

RunData runData(const Campaign& campaign, const Run& run, const DatasetOptions& options) {
    checkSampleTable(run);
    RunData data;
    data.run_id = run.id;
    data.kind = run.kind;
    data.target_channel = options.target_channel;
    data.reference_window_s = options.reference_window_s;
    if (options.target_channel.isEmpty()) {
        if (!isFeedAxisRun(run.kind))
            throw ModelError(QStringLiteral("run '%1' is a %2 run: its thermal error is in its "
                                            "displacement channels; choose one as the target "
                                            "(%3)")
                                 .arg(run.id, toString(run.kind),
                                      displacementChannels(campaign).join(QStringLiteral(", "))));
        if (!campaign.screw)
            throw ModelError(QStringLiteral("run '%1': the campaign has no screw, which the "
                                            "positioning error of a feed axis needs")
                                 .arg(run.id));
        data.observations = positioningErrors(run);
    } else {
        data.observations = driftErrors(run, options.target_channel, options.reference_window_s);
    }
    data.screw = campaign.screw;
    data.nut_length_mm = campaign.nut_length_mm;
    data.interferometer = campaign.interferometer;
    for (const Channel& channel : campaign.channels) {
        if (channel.quantity == Quantity::Temperature)
            data.temperatures.push_back(temperatureRise(run, channel, options));
        else if (channel.quantity == Quantity::Speed && data.spindle_speed_rpm.name.isEmpty())
            data.spindle_speed_rpm = presentSamples(run, channel.id);
    }
    data.position_mm = presentSamples(run, kPositionColumn);
    data.feed_mm_min = presentSamples(run, kFeedColumn);
    data.torque_Nm = presentSamples(run, kTorqueColumn);
    data.motion = run.motion;
    judgeRunHoles(data, run.samples.time_s.empty() ? 0.0 : run.samples.time_s.back());
    leaveOutHoles(data);
    return data;
}

// One drive moves the axis in every run: it is identified over all of them,
// whichever the data set takes (the torque is an input, not what is fitted).
std::optional<DriveTorqueModel> campaignDrive(const Campaign& campaign) {
    std::vector<RunData> runs;
    for (const Run& run : campaign.runs) {
        if (!isFeedAxisRun(run.kind)) continue;
        RunData drive;
        drive.run_id = run.id;
        drive.screw = campaign.screw;
        drive.torque_Nm = presentSamples(run, kTorqueColumn);
        drive.motion = run.motion;
        runs.push_back(std::move(drive));
    }
    return identifyDriveTorque(runs);
}

}  // namespace

std::vector<PredictionPoint> RunData::observationPoints() const {
    std::vector<PredictionPoint> points;
    points.reserve(observations.size());
    for (const ErrorObservation& o : observations) points.push_back({o.time_s, o.position_mm});
    return points;
}

Eigen::VectorXd RunData::observedErrors() const {
    Eigen::VectorXd e(Eigen::Index(observations.size()));
    for (std::size_t i = 0; i < observations.size(); ++i)
        e[Eigen::Index(i)] = observations[i].error_um;
    return e;
}

DatasetResult buildDataset(const Campaign& campaign, const QStringList& runIds,
                           const DatasetOptions& options) {
    DatasetResult result;
    try {
        if (runIds.isEmpty()) throw ModelError(QStringLiteral("no runs selected"));
        if (!(options.reference_window_s >= 0))
            throw ModelError(QStringLiteral("the reference window must not be negative"));
        checkTarget(campaign, options.target_channel);
        std::set<QString> seen;
        for (const QString& id : runIds) {
            if (!seen.insert(id).second)
                throw ModelError(QStringLiteral("run '%1' is selected twice").arg(id));
            const Run* run = campaign.findRun(id);
            if (!run)
                throw ModelError(
                    QStringLiteral("run '%1' is not in campaign '%2'").arg(id, campaign.name));
            result.runs.push_back(runData(campaign, *run, options));
        }
        if (const auto drive = campaignDrive(campaign))
            for (RunData& r : result.runs)
                if (instantaneousTorqueLog(r)) r.drive_torque = drive;
    } catch (const ModelError& e) {
        result.runs.clear();
        result.error = e.message;
    }
    return result;
}

}  // namespace driftlab::models
