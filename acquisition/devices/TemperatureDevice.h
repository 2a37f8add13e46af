#pragma once
// A temperature module polled on its own thread (DeviceThread): readings,
// errors once per connect cycle, gaps and health as queued signals, over
// Modbus TCP or RTU as the URL says (docs/devices.md).

#include <QObject>

#include "acquisition/devices/DeviceFacade.h"
#include "acquisition/devices/TemperatureModule.h"

namespace driftlab::devices {

class TemperatureDevice : public DeviceFacade {
    Q_OBJECT
public:
    TemperatureDevice(ChannelRegisterMap map, modbus::ModbusUrl url,
                      DeviceWorkerOptions options = {}, QObject* parent = nullptr);

signals:
    void readingReady(const driftlab::devices::TemperatureReading& reading);
};

}  // namespace driftlab::devices
