#include "acquisition/devices/ControllerLink.h"

#include <vector>

#include "acquisition/modbus/ModbusLink.h"
#include "acquisition/push/CompensationRegisterMap.h"

namespace driftlab::devices {
namespace {

/// Registers 0…13: identity, machine state, the report flag and the axis state.
constexpr int kReadCount = push::reg::kAxisTorque + 1;

}  // namespace

ControllerLink::ControllerLink(modbus::ModbusUrl url, double response_timeout_s)
    : m_link(std::make_unique<modbus::ModbusLink>(std::move(url), response_timeout_s)) {}

ControllerLink::~ControllerLink() = default;

bool ControllerLink::connect(QString* error) {
    return m_link->connect(error);
}

void ControllerLink::close() {
    m_link->close();
}

bool ControllerLink::isConnected() const {
    return m_link->isConnected();
}

int ControllerLink::requests() const {
    return m_link->requests();
}

std::optional<ControllerReading> ControllerLink::read(QString* error) {
    std::vector<std::uint16_t> words;
    if (!m_link->readRegisters(0, kReadCount, words, error)) {
        m_link->close();  // an exception too: a controller without block 0 is no controller link
        return std::nullopt;
    }
    const auto refuse = [&](const QString& why) {
        *error = QStringLiteral("%1: %2").arg(m_link->url().endpoint(), why);
        m_link->close();
        return std::nullopt;
    };
    namespace reg = push::reg;
    if (words[reg::kMagic] != push::kMagicValue ||
        words[reg::kMapVersion] != push::kMapVersionValue)
        return refuse(QStringLiteral("not DriftLab's register map (registers 0–1 hold 0x%1 %2, "
                                     "expected 0x%3 %4)")
                          .arg(words[reg::kMagic], 4, 16, QLatin1Char('0'))
                          .arg(words[reg::kMapVersion])
                          .arg(push::kMagicValue, 4, 16, QLatin1Char('0'))
                          .arg(push::kMapVersionValue));
    if (words[reg::kAxisReport] != 1)
        return refuse(QStringLiteral("the controller does not report the axis state "
                                     "(register 8 axis_report holds %1, expected 1)")
                          .arg(words[reg::kAxisReport]));
    const int state = words[reg::kMachineState];
    if (state > int(MachineState::ToolChange))
        return refuse(QStringLiteral("register 2 machine_state holds %1, not 0–3 "
                                     "(idle, moving, cutting, tool change)")
                          .arg(state));
    const AxisState axis = decodeAxisState(std::span<const std::uint16_t, kAxisStateRegisters>(
        &words[reg::kAxisPosition], kAxisStateRegisters));
    ControllerReading reading;
    reading.time_utc = QDateTime::currentDateTimeUtc();
    reading.position_mm = axis.position_mm;
    reading.feed_mm_min = axis.feed_mm_min;
    reading.torque_Nm = axis.torque_Nm;
    reading.state = MachineState(state);
    return reading;
}

std::optional<PolledReading> ControllerLink::poll(QString* error) {
    std::optional<ControllerReading> reading = read(error);
    if (!reading) return std::nullopt;
    return PolledReading{reading->time_utc, QVariant::fromValue(*reading)};
}

ControllerDevice::ControllerDevice(modbus::ModbusUrl url, DeviceWorkerOptions options,
                                   QObject* parent)
    : DeviceFacade(
          [url, timeout_s = options.response_timeout_s] {
              return std::make_unique<ControllerLink>(url, timeout_s);
          },
          QStringLiteral("controller %1").arg(url.endpoint()), options, parent) {
    qRegisterMetaType<ControllerReading>();
    forwardReadings<ControllerReading>(this);
}

}  // namespace driftlab::devices
