#include "acquisition/engine/DeviceRunSource.h"

#include <limits>

#include "acquisition/engine/DeviceEvents.h"

namespace driftlab::engine {

DeviceRunSource::DeviceRunSource(const DeviceRigSpec& spec, const std::vector<QString>& columns,
                                 const procedures::PlannedRun& run)
    : m_columns(columns),
      m_duration_s(run.duration_s),
      m_stale_ms(qint64(3000 * spec.poll_interval_s)),
      m_latest(columns.size(), std::numeric_limits<double>::quiet_NaN()),
      m_readAt(columns.size()),
      m_connectTimeout_ms(qint64(1000 * spec.connect_timeout_s)),
      m_matcher(run.programme.measurements, spec.target_tolerance_mm) {
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
    watchFirstReading(m_temperature.get(),
                      temperatureModuleSource(spec.temperature_url.endpoint()));
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
        watchFirstReading(m_controller.get(),
                          QStringLiteral("controller %1").arg(spec.controller_url->endpoint()));
        m_controller->start();
    }
    if (spec.interferometer) startInterferometer(*spec.interferometer, options);
}

DeviceRunSource::~DeviceRunSource() {
    if (m_interferometer) m_interferometer->stopAndWait();
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
        m_events.push_back(deviceLostEvent(source, message));
    });
    QObject::connect(
        device, &Device::gap, [this, source](const QDateTime& from, const QDateTime& to) {
            m_lostDevices = std::max(0, m_lostDevices - 1);
            m_events.push_back(deviceBackEvent(source, from.toString(Qt::ISODateWithMs),
                                               to.toString(Qt::ISODateWithMs),
                                               from.msecsTo(to) / 1000.0));
        });
}

template <typename Device>
void DeviceRunSource::watchFirstReading(Device* device, const QString& source) {
    watch(device, source);
    const std::size_t k = m_awaited.size();
    m_awaited.push_back({source, false, {}});
    QObject::connect(device, &Device::readingReady, [this, k] { m_awaited[k].answered = true; });
    QObject::connect(device, &Device::errorOccurred,
                     [this, k](const QString& message) { m_awaited[k].last_error = message; });
}

QString DeviceRunSource::failure() const {
    if (m_startedUtc.msecsTo(QDateTime::currentDateTimeUtc()) < m_connectTimeout_ms) return {};
    for (const Awaited& device : m_awaited)
        if (!device.answered)
            return QStringLiteral(
                       "%1: no reading within %2 s of the start (%3); check its "
                       "address and that it is powered")
                .arg(device.source)
                .arg(m_connectTimeout_ms / 1000.0)
                .arg(device.last_error.isEmpty() ? QStringLiteral("no answer") : device.last_error);
    return {};
}

void DeviceRunSource::startInterferometer(const devices::InterferometerStreamOptions& options,
                                          const devices::DeviceWorkerOptions& worker) {
    m_interferometerSource =
        QStringLiteral("interferometer %1:%2").arg(options.host).arg(options.port);
    m_interferometer = std::make_unique<devices::InterferometerDevice>(options, worker);
    QObject::connect(m_interferometer.get(), &devices::InterferometerDevice::readingReady,
                     [this](const devices::InterferometerBatch& batch) {
                         for (const auto& r : batch.readings) takeReading(r);
                     });
    watch(m_interferometer.get(), m_interferometerSource);
    m_interferometer->start();
}

void DeviceRunSource::takeReading(const devices::TimedInterferometerReading& r) {
    const QString& correction = r.reading.correction.description;
    if (correction != m_correction)
        m_events.push_back({QStringLiteral("info"), m_interferometerSource,
                            QStringLiteral("environment correction: %1").arg(correction)});
    m_correction = correction;
    const double position_mm = r.reading.position_mm;
    const auto planned = m_matcher.match(position_mm);
    if (!planned) {
        // Once per burst: a machine off its programme would otherwise flood the log.
        if (!m_unmatchedBurst)
            m_events.push_back(
                {QStringLiteral("warning"), m_interferometerSource,
                 QStringLiteral("reading at %1 mm matches no planned target (within ±%2 mm, "
                                "after the last matched); not stored")
                     .arg(position_mm, 0, 'f', 4)
                     .arg(m_matcher.tolerance_mm())});
        m_unmatchedBurst = true;
        return;
    }
    m_unmatchedBurst = false;
    const double time_s = m_anchor_s + m_anchorWall.msecsTo(r.time_utc) / 1000.0;
    m_readings.push_back({std::max(0.0, time_s), planned->cycle, planned->target_mm,
                          planned->direction, r.reading.deviation_um});
}

void DeviceRunSource::advanceTo(double until_s, rig::RunOutput& out) {
    const QDateTime now = QDateTime::currentDateTimeUtc();
    for (PositioningMeasurement& p : m_readings) {
        // A reading is due by the advance after it arrived.
        p.time_s = std::min(p.time_s, until_s);
        out.readings.push_back(p);
    }
    m_readings.clear();
    m_anchorWall = now;
    m_anchor_s = until_s;
    out.time_s.push_back(until_s);
    for (std::size_t c = 0; c < m_latest.size(); ++c) {
        const bool fresh = m_readAt[c].isValid() && m_readAt[c].msecsTo(now) <= m_stale_ms;
        out.rows.push_back(fresh ? m_latest[c] : std::numeric_limits<double>::quiet_NaN());
    }
    m_t = until_s;
}

void DeviceRunSource::replan(const procedures::PlannedRun& run) {
    m_matcher.replan(run.programme.measurements);
    m_events.push_back({QStringLiteral("info"), QStringLiteral("engine"),
                        QStringLiteral("the stabilisation criterion holds: end the warm-up on "
                                       "the machine now")});
}

}  // namespace driftlab::engine
