#include "acquisition/engine/DeviceRunSource.h"

#include <limits>

namespace driftlab::engine {

DeviceRunSource::DeviceRunSource(const DeviceRigSpec& spec, const std::vector<QString>& columns,
                                 double duration_s)
    : m_columns(columns),
      m_duration_s(duration_s),
      m_stale_ms(qint64(3000 * spec.poll_interval_s)),
      m_latest(columns.size(), std::numeric_limits<double>::quiet_NaN()),
      m_readAt(columns.size()) {
    devices::DeviceWorkerOptions options;
    options.poll_interval_s = spec.poll_interval_s;
    for (const auto& channel : spec.temperature_map.channels)
        m_temperatureColumn.push_back(columnOf(channel.id));
    m_temperature = std::make_unique<devices::TemperatureDevice>(spec.temperature_map,
                                                                 spec.temperature_url, options);
    QObject::connect(m_temperature.get(), &devices::TemperatureDevice::readingReady,
                     [this](const devices::TemperatureReading& r) {
                         for (std::size_t k = 0; k < r.values.size(); ++k)
                             if (k < m_temperatureColumn.size())
                                 set(m_temperatureColumn[k], r.values[k], r.time_utc);
                     });
    watch(m_temperature.get(),
          QStringLiteral("temperature module %1").arg(spec.temperature_url.endpoint()));
    m_temperature->start();
    if (spec.controller_url) {
        m_controller = std::make_unique<devices::ControllerDevice>(*spec.controller_url, options);
        QObject::connect(
            m_controller.get(), &devices::ControllerDevice::readingReady,
            [this](const devices::ControllerReading& r) {
                set(columnOf(kPositionColumn), r.position_mm, r.time_utc);
                set(columnOf(kFeedColumn), r.feed_mm_min, r.time_utc);
                set(columnOf(kTorqueColumn), r.torque_Nm, r.time_utc);
                if (m_machineState != r.state)
                    m_events.push_back(
                        {QStringLiteral("info"), QStringLiteral("controller"),
                         QStringLiteral("machine state: %1").arg(machineStateName(r.state))});
                m_machineState = r.state;
            });
        watch(m_controller.get(),
              QStringLiteral("controller %1").arg(spec.controller_url->endpoint()));
        m_controller->start();
    }
}

DeviceRunSource::~DeviceRunSource() {
    if (m_controller) m_controller->stopAndWait();
    m_temperature->stopAndWait();
}

int DeviceRunSource::columnOf(const QString& id) const {
    const auto it = std::find(m_columns.begin(), m_columns.end(), id);
    return it == m_columns.end() ? -1 : int(it - m_columns.begin());
}

void DeviceRunSource::set(int column, double value, const QDateTime& at) {
    if (column < 0) return;
    m_latest[std::size_t(column)] = value;
    m_readAt[std::size_t(column)] = at;
}

template <typename Device>
void DeviceRunSource::watch(Device* device, const QString& source) {
    // One error per connect cycle (the worker's rule), so one "lost" per outage.
    QObject::connect(device, &Device::errorOccurred, [this, source](const QString& message) {
        ++m_lostDevices;
        m_events.push_back({QStringLiteral("error"), source, message});
    });
    QObject::connect(
        device, &Device::gap, [this, source](const QDateTime& from, const QDateTime& to) {
            m_lostDevices = std::max(0, m_lostDevices - 1);
            m_events.push_back(
                {QStringLiteral("warning"), source,
                 QStringLiteral("gap: no data from %1 to %2 (%3 s); reconnected")
                     .arg(from.toString(Qt::ISODateWithMs), to.toString(Qt::ISODateWithMs))
                     .arg(from.msecsTo(to) / 1000.0)});
        });
}

void DeviceRunSource::advanceTo(double until_s, rig::RunOutput& out) {
    const QDateTime now = QDateTime::currentDateTimeUtc();
    out.time_s.push_back(until_s);
    for (std::size_t c = 0; c < m_latest.size(); ++c) {
        const bool fresh = m_readAt[c].isValid() && m_readAt[c].msecsTo(now) <= m_stale_ms;
        out.rows.push_back(fresh ? m_latest[c] : std::numeric_limits<double>::quiet_NaN());
    }
    m_t = until_s;
}

void DeviceRunSource::replan(const procedures::PlannedRun&) {
    m_events.push_back({QStringLiteral("info"), QStringLiteral("engine"),
                        QStringLiteral("the stabilisation criterion holds: end the warm-up on "
                                       "the machine now")});
}

}  // namespace driftlab::engine
