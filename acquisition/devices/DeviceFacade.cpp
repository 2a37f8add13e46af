#include "acquisition/devices/DeviceFacade.h"

namespace driftlab::devices {

DeviceFacade::DeviceFacade(PolledDeviceFactory make_device, const QString& name,
                           DeviceWorkerOptions options, QObject* parent)
    : QObject(parent), m_thread(std::move(make_device), name, options, this) {
    connect(&m_thread, &DeviceThread::errorOccurred, this, &DeviceFacade::errorOccurred);
    connect(&m_thread, &DeviceThread::gap, this, &DeviceFacade::gap);
    connect(&m_thread, &DeviceThread::healthChanged, this, &DeviceFacade::healthChanged);
    connect(&m_thread, &DeviceThread::attemptFailed, this, &DeviceFacade::attemptFailed);
}

}  // namespace driftlab::devices
