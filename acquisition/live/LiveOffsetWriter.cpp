#include "acquisition/live/LiveOffsetWriter.h"

#include <array>
#include <cmath>
#include <limits>

#include "acquisition/push/CompensationRegisterMap.h"

namespace driftlab::live {

namespace reg = push::reg;

LiveOffsetWriter::LiveOffsetWriter(modbus::ModbusUrl url, double response_timeout_s,
                                   int stale_after_s)
    : m_link(std::move(url), response_timeout_s), m_staleAfter_s(stale_after_s) {}

bool LiveOffsetWriter::open(QString* error) {
    if (m_staleAfter_s < 1 || m_staleAfter_s > 65535) {
        *error = QStringLiteral("live_timeout_s %1 s is not within 1…65535").arg(m_staleAfter_s);
        return false;
    }
    if (!m_link.connect(error)) return false;
    std::vector<std::uint16_t> block0;
    if (!m_link.readRegisters(reg::kMagic, 2, block0, error)) return false;
    if (block0[0] != push::kMagicValue || block0[1] != push::kMapVersionValue) {
        *error = QStringLiteral(
                     "%1 does not serve DriftLab's register map version %2 (register 0 "
                     "holds 0x%3, register 1 holds %4)")
                     .arg(m_link.url().endpoint())
                     .arg(push::kMapVersionValue)
                     .arg(block0[0], 4, 16, QLatin1Char('0'))
                     .arg(block0[1]);
        return false;
    }
    // Continue the controller's sequence: a restarted DriftLab must not send
    // the number the controller already holds, which it would ignore.
    std::vector<std::uint16_t> live;
    if (!m_link.readRegisters(reg::kLiveFirst, 1, live, error)) return false;
    m_sequence = live[0];
    return true;
}

std::optional<MachineState> LiveOffsetWriter::machineState(QString* error) {
    std::vector<std::uint16_t> state;
    if (!m_link.readRegisters(reg::kMachineState, 1, state, error)) return std::nullopt;
    return MachineState(state[0]);
}

bool LiveOffsetWriter::publish(double offset_um, bool enable, QString* error) {
    const double nm = std::round(offset_um * 1000);
    if (!std::isfinite(nm) || std::abs(nm) > std::numeric_limits<std::int32_t>::max()) {
        *error = QStringLiteral("live offset %1 µm does not fit the register map (int32 nm)")
                     .arg(offset_um);
        return false;
    }
    std::array<std::uint16_t, 5> block3{};
    block3[0] = std::uint16_t(m_sequence + 1);
    push::putInt32(std::int32_t(nm), &block3[1]);
    block3[3] = enable ? 1 : 0;
    block3[4] = std::uint16_t(m_staleAfter_s);
    if (!m_link.writeRegisters(reg::kLiveFirst, block3, error)) return false;
    m_sequence = block3[0];
    return true;
}

}  // namespace driftlab::live
