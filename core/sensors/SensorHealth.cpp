#include "core/sensors/SensorHealth.h"

#include <QStringList>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace driftlab::sensors {
namespace {

void requireValid(const SensorHealthSettings& settings) {
    QString error;
    if (!settings.isValid(&error)) throw std::invalid_argument(error.toStdString());
}

const std::vector<double>& column(const SampleSeries& series, const QString& id) {
    const int index = series.columnIndex(id);
    if (index < 0)
        throw std::invalid_argument(
            QStringLiteral("no column %1 in the samples").arg(id).toStdString());
    return series.values[static_cast<std::size_t>(index)];
}

}  // namespace

RedundantPairChecker::RedundantPairChecker(SensorHealthSettings settings) : m_settings(settings) {
    requireValid(m_settings);
}

std::optional<double> RedundantPairChecker::offset() const {
    if (!m_baseline_done) return std::nullopt;
    return m_sum / static_cast<double>(m_count);
}

SensorFlags RedundantPairChecker::push(double time_s, double first, double second) {
    if (!std::isfinite(first) || !std::isfinite(second)) return kNoFlags;
    const double difference = first - second;
    if (!m_start_s) m_start_s = time_s;
    if (!m_baseline_done) {
        // The pair's calibration offset is whatever it is at the start; only
        // a change of it is a fault.
        if (time_s - *m_start_s < m_settings.redundant_baseline_s) {
            m_sum += difference;
            ++m_count;
            m_last_s = time_s;
            return kNoFlags;
        }
        m_baseline_done = true;
    }
    const double divergence = difference - *offset();
    const double dt_s = std::max(0.0, time_s - *m_last_s);
    // Exponential smoothing over redundant_smoothing_s: the noise of two
    // sensors and their slightly different lags must not look like drift.
    const double weight = m_settings.redundant_smoothing_s > 0
                              ? 1.0 - std::exp(-dt_s / m_settings.redundant_smoothing_s)
                              : 1.0;
    m_smoothed += weight * (divergence - m_smoothed);
    m_last_s = time_s;
    return std::abs(m_smoothed) > m_settings.redundant_drift_limit_K
               ? bit(SensorFault::RedundantDrift)
               : kNoFlags;
}

ChannelHealthSummary summarise(const QString& channel, const std::vector<double>& time_s,
                               const std::vector<SensorFlags>& flags) {
    SummaryBuilder builder(channel);
    for (std::size_t i = 0; i < flags.size(); ++i) builder.add({i, time_s[i], flags[i]});
    return builder.summary();
}

ChannelHealth checkColumn(const SampleSeries& series, const Channel& channel,
                          const SensorHealthSettings& settings) {
    requireValid(settings);
    const QString& id = channel.id;
    const std::vector<double>& values = column(series, id);
    ChannelHealth health;
    health.flags.assign(series.rowCount(), kNoFlags);
    ChannelHealthChecker checker(id, channel.quantity,
                                 applicableChecks(channel.quantity, channel.role), settings);
    auto apply = [&](const HealthUpdate& update) {
        for (const auto& v : update.verdicts) health.flags[v.index] |= v.flags;
        if (update.backfill)
            for (std::size_t i = update.backfill->first_index; i <= update.backfill->last_index;
                 ++i)
                health.flags[i] |= bit(SensorFault::Frozen);
    };
    for (std::size_t i = 0; i < series.rowCount(); ++i)
        apply(checker.push(series.time_s[i], values[i]));
    apply(checker.finish());
    health.summary = summarise(id, series.time_s, health.flags);
    return health;
}

std::map<QString, ChannelHealth> checkRun(const SampleSeries& series,
                                          const std::vector<Channel>& channels,
                                          const std::vector<RedundantPair>& redundant,
                                          const SensorHealthSettings& settings) {
    requireValid(settings);
    std::map<QString, ChannelHealth> result;
    std::map<QString, Quantity> quantities;
    for (const Channel& channel : channels) {
        if (series.columnIndex(channel.id) < 0) continue;
        quantities[channel.id] = channel.quantity;
        result[channel.id] = checkColumn(series, channel, settings);
    }
    for (const RedundantPair& pair : redundant) {
        for (const QString& id : {pair.first, pair.second})
            if (!quantities.contains(id) || quantities.at(id) != Quantity::Temperature)
                throw std::invalid_argument(
                    QStringLiteral("redundant pair %1/%2: %3 is not a temperature channel of "
                                   "the samples")
                        .arg(pair.first, pair.second, id)
                        .toStdString());
        if (pair.first == pair.second)
            throw std::invalid_argument(
                QStringLiteral("redundant pair names %1 twice").arg(pair.first).toStdString());
        const std::vector<double>& a = column(series, pair.first);
        const std::vector<double>& b = column(series, pair.second);
        ChannelHealth& healthA = result.at(pair.first);
        ChannelHealth& healthB = result.at(pair.second);
        RedundantPairChecker checker(settings);
        constexpr double kSkip = std::numeric_limits<double>::quiet_NaN();
        for (std::size_t i = 0; i < series.rowCount(); ++i) {
            // A spike or an open element must not enter the pair's difference.
            constexpr SensorFlags kSingleChannel = ~bit(SensorFault::RedundantDrift);
            const bool clean = (healthA.flags[i] & kSingleChannel) == kNoFlags &&
                               (healthB.flags[i] & kSingleChannel) == kNoFlags;
            const SensorFlags flag =
                checker.push(series.time_s[i], clean ? a[i] : kSkip, clean ? b[i] : kSkip);
            healthA.flags[i] |= flag;
            healthB.flags[i] |= flag;
        }
    }
    for (auto& [id, health] : result) health.summary = summarise(id, series.time_s, health.flags);
    return result;
}

std::optional<RedundantPair> parseRedundantPair(const QString& text) {
    const QStringList two = text.split(QLatin1Char('='));
    if (two.size() != 2) return std::nullopt;
    RedundantPair pair{two[0].trimmed(), two[1].trimmed()};
    if (pair.first.isEmpty() || pair.second.isEmpty()) return std::nullopt;
    return pair;
}

}  // namespace driftlab::sensors
