#include "acquisition/engine/DeviceRig.h"

#include <cmath>
#include <limits>

#include "acquisition/devices/TemperatureDevice.h"

namespace driftlab::engine {
namespace {

/// Logs the latest reading of each channel at the procedure's sample times;
/// a reading older than three polls counts as missing.
class DeviceRunSource : public RunSource {
public:
    DeviceRunSource(const DeviceRigSpec& spec, const std::vector<QString>& columns,
                    double duration_s)
        : m_duration_s(duration_s),
          m_stale_ms(qint64(3000 * spec.poll_interval_s)),
          m_latest(columns.size(), std::numeric_limits<double>::quiet_NaN()),
          m_readAt(columns.size()) {
        for (const auto& channel : spec.temperature_map.channels) {
            const auto it = std::find(columns.begin(), columns.end(), channel.id);
            m_column.push_back(it == columns.end() ? -1 : int(it - columns.begin()));
        }
        devices::DeviceWorkerOptions options;
        options.poll_interval_s = spec.poll_interval_s;
        m_device = std::make_unique<devices::TemperatureDevice>(spec.temperature_map,
                                                                spec.temperature_url, options);
        const QString source = QStringLiteral("temperature module %1:%2")
                                   .arg(spec.temperature_url.host)
                                   .arg(spec.temperature_url.port);
        QObject::connect(m_device.get(), &devices::TemperatureDevice::readingReady,
                         [this](const devices::TemperatureReading& r) {
                             for (std::size_t k = 0; k < r.values.size() && k < m_column.size();
                                  ++k)
                                 if (m_column[k] >= 0) {
                                     m_latest[std::size_t(m_column[k])] = r.values[k];
                                     m_readAt[std::size_t(m_column[k])] = r.time_utc;
                                 }
                         });
        QObject::connect(m_device.get(), &devices::TemperatureDevice::errorOccurred,
                         [this, source](const QString& message) {
                             m_lost = true;
                             m_events.push_back({QStringLiteral("error"), source, message});
                         });
        QObject::connect(
            m_device.get(), &devices::TemperatureDevice::gap,
            [this, source](const QDateTime& from, const QDateTime& to) {
                m_lost = false;
                m_events.push_back(
                    {QStringLiteral("warning"), source,
                     QStringLiteral("gap: no data from %1 to %2 (%3 s); reconnected")
                         .arg(from.toString(Qt::ISODateWithMs), to.toString(Qt::ISODateWithMs))
                         .arg(from.msecsTo(to) / 1000.0)});
            });
        m_device->start();
    }
    ~DeviceRunSource() override { m_device->stopAndWait(); }

    void advanceTo(double until_s, rig::RunOutput& out) override {
        const QDateTime now = QDateTime::currentDateTimeUtc();
        out.time_s.push_back(until_s);
        for (std::size_t c = 0; c < m_latest.size(); ++c) {
            const bool fresh = m_readAt[c].isValid() && m_readAt[c].msecsTo(now) <= m_stale_ms;
            out.rows.push_back(fresh ? m_latest[c] : std::numeric_limits<double>::quiet_NaN());
        }
        m_t = until_s;
    }
    double time_s() const override { return m_t; }
    bool finished() const override { return m_t >= m_duration_s - 1e-9; }
    void replan(const procedures::PlannedRun&) override {
        m_events.push_back({QStringLiteral("info"), QStringLiteral("engine"),
                            QStringLiteral("the stabilisation criterion holds: end the warm-up "
                                           "on the machine now")});
    }
    std::vector<SourceEvent> takeEvents() override { return std::exchange(m_events, {}); }
    bool deviceLost() const override { return m_lost; }

private:
    double m_duration_s, m_t = 0;
    qint64 m_stale_ms;
    std::vector<int> m_column;  ///< campaign column of each map channel, or -1
    std::vector<double> m_latest;
    std::vector<QDateTime> m_readAt;
    std::vector<SourceEvent> m_events;
    bool m_lost = false;
    std::unique_ptr<devices::TemperatureDevice> m_device;
};

}  // namespace

DeviceRig::DeviceRig(DeviceRigSpec spec) : m_spec(std::move(spec)) {}

QString DeviceRig::describe() const {
    return QStringLiteral("temperature module %1 at %2:%3")
        .arg(m_spec.temperature_map.name, m_spec.temperature_url.host)
        .arg(m_spec.temperature_url.port);
}

Campaign DeviceRig::campaignHeader(const std::vector<procedures::PlannedRun>&) const {
    Campaign c;
    if (m_spec.campaign_template) {
        c = *m_spec.campaign_template;
        c.runs.clear();
    } else {
        c.machine.name = QStringLiteral("machine on %1").arg(m_spec.temperature_url.host);
        for (const auto& channel : m_spec.temperature_map.channels)
            c.channels.push_back({channel.id,
                                  Quantity::Temperature,
                                  ChannelRole::Other,
                                  QStringLiteral("temperature module channel"),
                                  std::nullopt,
                                  {}});
    }
    c.sample_columns.clear();
    for (const auto& channel : c.channels) c.sample_columns.push_back(channel.id);
    return c;
}

std::unique_ptr<RunSource> DeviceRig::open(const procedures::PlannedRun& run, std::size_t,
                                           const std::vector<QString>& columns, QString*) {
    return std::make_unique<DeviceRunSource>(m_spec, columns, run.duration_s);
}

}  // namespace driftlab::engine
