#include "acquisition/devices/TemperatureDevice.h"

namespace driftlab::devices {

TemperatureDevice::TemperatureDevice(ChannelRegisterMap map, modbus::ModbusUrl url,
                                     DeviceWorkerOptions options, QObject* parent)
    : QObject(parent),
      m_thread(
          [map = std::move(map), url, timeout_s = options.response_timeout_s] {
              return std::make_unique<TemperatureModule>(map, url, timeout_s);
          },
          QStringLiteral("device %1").arg(url.endpoint()), options, this) {
    qRegisterMetaType<TemperatureReading>();
    forwardDeviceSignals<TemperatureReading>(&m_thread, this);
}

}  // namespace driftlab::devices
