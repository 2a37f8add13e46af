#pragma once
// The run source of a DeviceRig: the latest reading of every device, logged
// at the procedure's sample times. A reading older than three polls counts
// as missing (NaN), so a lost device leaves a hole in its columns only; its
// outage and reconnect are events, and machine-state changes too.
// Interferometer readings are matched to the planned measurements
// (TargetMatcher) and logged as positioning readings at their run time.

#include <QDateTime>

#include "acquisition/devices/ControllerLink.h"
#include "acquisition/devices/InterferometerDevice.h"
#include "acquisition/devices/TemperatureDevice.h"
#include "acquisition/engine/DeviceRig.h"
#include "acquisition/engine/TargetMatcher.h"

namespace driftlab::engine {

class DeviceRunSource : public RunSource {
public:
    DeviceRunSource(const DeviceRigSpec& spec, const std::vector<QString>& columns,
                    const procedures::PlannedRun& run);
    ~DeviceRunSource() override;

    void advanceTo(double until_s, rig::RunOutput& out) override;
    double time_s() const override { return m_t; }
    bool finished() const override { return m_t >= m_duration_s - 1e-9; }
    void replan(const procedures::PlannedRun& run) override;
    std::vector<SourceEvent> takeEvents() override { return std::exchange(m_events, {}); }
    bool deviceLost() const override { return m_lostDevices > 0; }
    QString failure() const override;

private:
    int columnOf(const QString& id) const;
    void set(int column, double value, const QDateTime& at);
    /// Errors and gaps of a device into events; counts it lost until its gap closes.
    template <typename Device>
    void watch(Device* device, const QString& source);
    /// As watch(), and the device must give a reading within the connect timeout.
    template <typename Device>
    void watchFirstReading(Device* device, const QString& source);
    void startInterferometer(const devices::InterferometerStreamOptions& options,
                             const devices::DeviceWorkerOptions& worker);
    /// Matches a reading to its planned measurement; logs the correction applied.
    void takeReading(const devices::TimedInterferometerReading& r);

    std::vector<QString> m_columns;
    double m_duration_s, m_t = 0;
    qint64 m_stale_ms;
    std::vector<double> m_latest;
    std::vector<QDateTime> m_readAt;
    std::vector<int> m_temperatureColumn;  ///< campaign column of each map channel, or -1
    std::vector<SourceEvent> m_events;
    int m_lostDevices = 0;
    /// A device that must answer within the connect timeout.
    struct Awaited {
        QString source;
        bool answered = false;
        QString last_error;
    };
    std::vector<Awaited> m_awaited;
    QDateTime m_startedUtc = QDateTime::currentDateTimeUtc();
    qint64 m_connectTimeout_ms;
    std::optional<MachineState> m_machineState;
    std::unique_ptr<devices::TemperatureDevice> m_temperature;
    std::unique_ptr<devices::ControllerDevice> m_controller;
    std::unique_ptr<devices::InterferometerDevice> m_interferometer;
    QString m_interferometerSource;
    TargetMatcher m_matcher;
    std::vector<PositioningMeasurement> m_readings;  ///< matched, not yet handed out
    QString m_correction;                            ///< the last one logged
    bool m_unmatchedBurst = false;
    /// Run time `m_anchor_s` was at wall time `m_anchorWall` (the last advance):
    /// a reading's run time is counted from there.
    QDateTime m_anchorWall = QDateTime::currentDateTimeUtc();
    double m_anchor_s = 0;
};

}  // namespace driftlab::engine
