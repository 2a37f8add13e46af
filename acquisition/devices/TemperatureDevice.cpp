#include "acquisition/devices/TemperatureDevice.h"

namespace driftlab::devices {

TemperatureDevice::TemperatureDevice(ChannelRegisterMap map, modbus::ModbusUrl url,
                                     DeviceWorkerOptions options, QObject* parent)
    : DeviceFacade(
          [map = std::move(map), url, timeout_s = options.response_timeout_s] {
              return std::make_unique<TemperatureModule>(map, url, timeout_s);
          },
          QStringLiteral("device %1").arg(url.endpoint()), options, parent) {
    qRegisterMetaType<TemperatureReading>();
    forwardReadings<TemperatureReading>(this);
}

}  // namespace driftlab::devices
