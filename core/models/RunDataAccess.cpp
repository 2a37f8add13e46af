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

ModelError gapError(const Signal& signal, const QString& runId, double from, double to,
                    double max_gap_s) {
    return ModelError(QStringLiteral("run '%1', %2: no sample between %3 s and %4 s, a gap "
                                     "longer than the %5 s limit")
                          .arg(runId, describeSignal(signal), messageNumber(from),
                               messageNumber(to), messageNumber(max_gap_s)));
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

double valueAt(const Signal& signal, double time_s, double runGap_s, const QString& runId) {
    const std::vector<double>& t = signal.time_s;
    if (t.empty()) throw noSamples(signal, runId);
    const double max_gap_s = signal.gapLimit_s(runGap_s);
    auto gap = [&](double from, double to) { return gapError(signal, runId, from, to, max_gap_s); };
    const auto hi = std::lower_bound(t.begin(), t.end(), time_s);
    const std::size_t i = std::size_t(hi - t.begin());
    if (hi != t.end() && *hi == time_s) return signal.value[i];
    if (i == 0) {
        if (t.front() - time_s > max_gap_s) throw gap(time_s, t.front());
        return signal.value.front();
    }
    if (i == t.size()) {
        if (time_s - t.back() > max_gap_s) throw gap(t.back(), time_s);
        return signal.value.back();
    }
    const double t0 = t[i - 1], t1 = t[i];
    if (t1 - t0 > max_gap_s) throw gap(t0, t1);
    const double w = (time_s - t0) / (t1 - t0);
    return (1 - w) * signal.value[i - 1] + w * signal.value[i];
}

void requireCoverage(const RunData& run, const Signal& signal, double until_s) {
    const std::vector<double>& t = signal.time_s;
    if (t.empty()) throw noSamples(signal, run.run_id);
    const double max_gap_s = signal.gapLimit_s(run.max_gap_s);
    auto check = [&](double from, double to) {
        if (to - from > max_gap_s) throw gapError(signal, run.run_id, from, to, max_gap_s);
    };
    check(0.0, t.front());
    for (std::size_t i = 1; i < t.size(); ++i) check(t[i - 1], t[i]);
    check(t.back(), until_s);
}

Eigen::MatrixXd risesAt(const RunData& run, const QStringList& channelIds,
                        const std::vector<PredictionPoint>& at) {
    Eigen::MatrixXd rises(Eigen::Index(at.size()), channelIds.size());
    for (qsizetype c = 0; c < channelIds.size(); ++c) {
        const TemperatureRise& channel = temperatureChannel(run, channelIds[c]);
        for (std::size_t p = 0; p < at.size(); ++p)
            rises(Eigen::Index(p), c) =
                valueAt(channel.rise_K, at[p].time_s, run.max_gap_s, run.run_id);
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
