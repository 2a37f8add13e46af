#include "core/models/RunDataAccess.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/models/ModelError.h"

namespace driftlab::models {
namespace {

const TemperatureRise& temperatureChannel(const RunData& run, const QString& id) {
    for (const TemperatureRise& t : run.temperatures)
        if (t.channel_id == id) {
            if (!t.unusable.isEmpty()) throw ModelError(t.unusable);
            return t;
        }
    throw ModelError(
        QStringLiteral("run '%1' has no temperature channel '%2'").arg(run.run_id, id));
}

ModelError holeError(const Signal& signal, const QString& runId, double from, double to) {
    return ModelError(
        QStringLiteral("run '%1', %2: no sample between %3 s and %4 s, a hole in "
                       "the log that its course on either side does not let "
                       "DriftLab bridge (its observations are left out)")
            .arg(runId, describeSignal(signal), messageNumber(from), messageNumber(to)));
}

ModelError noSamples(const Signal& signal, const QString& runId) {
    return ModelError(
        QStringLiteral("run '%1', %2: no samples in this run").arg(runId, describeSignal(signal)));
}

}  // namespace

QString describeSignal(const Signal& signal) {
    return (isAxisColumn(signal.name) ? QStringLiteral("column '%1'")
                                      : QStringLiteral("channel '%1'"))
        .arg(signal.name);
}

double valueAt(const Signal& signal, double time_s, const QString& runId) {
    const std::vector<double>& t = signal.time_s;
    if (t.empty()) throw noSamples(signal, runId);
    if (const SignalHole* hole = signal.leftOutHoleAt(time_s))
        throw holeError(signal, runId, hole->from_s, hole->to_s);
    if (time_s - t.back() > kHoleIntervals * signal.sampling_s)
        throw ModelError(QStringLiteral("run '%1', %2: no sample after %3 s (asked at %4 s)")
                             .arg(runId, describeSignal(signal), messageNumber(t.back()),
                                  messageNumber(time_s)));
    return bridgedValueAt(signal, time_s, runId);
}

double bridgedValueAt(const Signal& signal, double time_s, const QString& runId) {
    const std::vector<double>& t = signal.time_s;
    if (t.empty()) throw noSamples(signal, runId);
    const auto hi = std::lower_bound(t.begin(), t.end(), time_s);
    const std::size_t i = std::size_t(hi - t.begin());
    if (hi != t.end() && *hi == time_s) return signal.value[i];
    if (i == 0) return signal.value.front();
    if (i == t.size()) return signal.value.back();
    const double t0 = t[i - 1], t1 = t[i];
    const double w = (time_s - t0) / (t1 - t0);
    return (1 - w) * signal.value[i - 1] + w * signal.value[i];
}

void requireCoverage(const RunData& run, const Signal& signal) {
    if (signal.time_s.empty()) throw noSamples(signal, run.run_id);
    // From the run's start: an input first read later has no start to run from.
    const double latest_s =
        std::max(2 * run.reference_window_s, kHoleIntervals * signal.sampling_s);
    if (signal.time_s.front() > latest_s)
        throw ModelError(QStringLiteral("run '%1', %2: no sample between 0 s and %3 s, too late "
                                        "for the run's start (limit %4 s)")
                             .arg(run.run_id, describeSignal(signal),
                                  messageNumber(signal.time_s.front()), messageNumber(latest_s)));
}

Eigen::MatrixXd risesAt(const RunData& run, const QStringList& channelIds,
                        const std::vector<PredictionPoint>& at) {
    Eigen::MatrixXd rises(Eigen::Index(at.size()), channelIds.size());
    for (qsizetype c = 0; c < channelIds.size(); ++c) {
        const TemperatureRise& channel = temperatureChannel(run, channelIds[c]);
        for (std::size_t p = 0; p < at.size(); ++p)
            rises(Eigen::Index(p), c) = valueAt(channel.rise_K, at[p].time_s, run.run_id);
    }
    return rises;
}

QStringList unloggedChannels(const std::vector<RunData>& runs) {
    QStringList unlogged;
    for (const RunData& run : runs)
        for (const TemperatureRise& t : run.temperatures)
            if (t.rise_K.empty() && !unlogged.contains(t.channel_id)) unlogged << t.channel_id;
    return unlogged;
}

const TemperatureRise* firstUsableOfRole(const RunData& run, ChannelRole role) {
    for (const TemperatureRise& t : run.temperatures)
        if (t.role == role && t.unusable.isEmpty()) return &t;
    return nullptr;
}

const TemperatureRise& channelForRole(const RunData& run, ChannelRole role, const QString& model) {
    const TemperatureRise* best = nullptr;
    auto distance = [&](const TemperatureRise& t) {
        return t.position_mm ? std::abs(*t.position_mm - run.fixedEnd_mm())
                             : std::numeric_limits<double>::infinity();
    };
    for (const TemperatureRise& t : run.temperatures)
        if (t.role == role && (!best || distance(t) < distance(*best))) best = &t;
    if (!best)
        throw ModelError(QStringLiteral("model '%1' needs a temperature channel with role '%2'; "
                                        "this campaign has none")
                             .arg(model, toString(role)));
    return *best;
}

Eigen::VectorXd positionsFromFixedEnd(const RunData& run, const std::vector<PredictionPoint>& at) {
    Eigen::VectorXd dx(Eigen::Index(at.size()));
    for (std::size_t p = 0; p < at.size(); ++p)
        dx[Eigen::Index(p)] = at[p].position_mm - run.fixedEnd_mm();
    return dx;
}

Eigen::MatrixXd stackRows(const std::vector<RunData>& runs,
                          const std::function<Eigen::MatrixXd(const RunData&)>& perRun) {
    std::vector<Eigen::MatrixXd> parts;
    Eigen::Index rows = 0;
    for (const RunData& run : runs) {
        parts.push_back(perRun(run));
        rows += parts.back().rows();
    }
    Eigen::MatrixXd all(rows, parts.empty() ? 0 : parts.front().cols());
    Eigen::Index at = 0;
    for (const Eigen::MatrixXd& part : parts) {
        all.middleRows(at, part.rows()) = part;
        at += part.rows();
    }
    return all;
}

}  // namespace driftlab::models
