#pragma once
// The controller link: the axis state a CNC controller or PLC reports in block
// 0 of DriftLab's register map (docs/modbus-register-map.md) — actual
// position, feed, motor torque and machine state — read in one request of
// registers 0…13 over Modbus TCP (or RTU: the URL decides). Like ModbusLink
// it belongs to the thread that created it; ControllerDevice polls it on its
// own thread.

#include <QDateTime>
#include <QObject>
#include <QString>
#include <memory>
#include <optional>

#include "acquisition/devices/AxisStateRegisters.h"
#include "acquisition/devices/DeviceFacade.h"
#include "acquisition/devices/PolledDevice.h"
#include "acquisition/modbus/ModbusUrl.h"
#include "core/domain/MachineState.h"

namespace driftlab::modbus {
class ModbusLink;
}

namespace driftlab::devices {

struct ControllerReading {
    QDateTime time_utc;  ///< taken after the request: the values are at most this old
    double position_mm = 0;
    double feed_mm_min = 0;  ///< signed: the direction of travel
    double torque_Nm = 0;
    MachineState state = MachineState::Idle;
};

class ControllerLink : public PolledDevice {
public:
    explicit ControllerLink(modbus::ModbusUrl url, double response_timeout_s = 1.0);
    ~ControllerLink() override;
    ControllerLink(const ControllerLink&) = delete;
    ControllerLink& operator=(const ControllerLink&) = delete;

    bool connect(QString* error) override;
    void close() override;
    bool isConnected() const;

    /// The axis state, or nullopt with `error`, the link then closed: the
    /// transport failed, or the controller does not serve the map (magic,
    /// version), does not report the axis state (register 8 is 0) or reports
    /// a machine state outside 0…3 (never guessed: a wrong "idle" would let a
    /// table change mid-cut).
    std::optional<ControllerReading> read(QString* error);
    std::optional<PolledReading> poll(QString* error) override;

    /// Requests sent so far (one per read).
    int requests() const;

private:
    std::unique_ptr<modbus::ModbusLink> m_link;
};

/// A controller link polled on its own thread (DeviceThread): readings,
/// one error per connect cycle, gaps and health as queued signals.
class ControllerDevice : public DeviceFacade {
    Q_OBJECT
public:
    explicit ControllerDevice(modbus::ModbusUrl url, DeviceWorkerOptions options = {},
                              QObject* parent = nullptr);

signals:
    void readingReady(const driftlab::devices::ControllerReading& reading);
};

}  // namespace driftlab::devices

Q_DECLARE_METATYPE(driftlab::devices::ControllerReading)
