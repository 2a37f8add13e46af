#pragma once
// Writes live thermal offsets to a controller's block 3 of DriftLab's Modbus
// register map (docs/modbus-register-map.md) and reads its machine state from
// block 0: the path to LinuxCNC's external offsets (resources/linuxcnc/
// driftlab_eoffset.py) and to PLC-based controllers. One update is one write
// request of registers 2000…2004, so the controller never sees a new sequence
// number with an old offset.

#include <QString>
#include <optional>

#include "acquisition/modbus/ModbusLink.h"
#include "core/domain/MachineState.h"

namespace driftlab::live {

class LiveOffsetWriter {
public:
    /// `stale_after_s`: live_timeout_s, how long the controller holds an
    /// offset without a new one before it flags it stale (1…65535).
    LiveOffsetWriter(modbus::ModbusUrl url, double response_timeout_s, int stale_after_s);

    /// Connects and checks that the map is served (magic, map version).
    bool open(QString* error);
    /// The machine state in block 0.
    std::optional<MachineState> machineState(QString* error);
    /// The next sequence number with `offset_um` (rounded to nm) and enable.
    /// Refuses an offset beyond int32 nm (±2.1 m) before writing.
    bool publish(double offset_um, bool enable, QString* error);

    std::uint16_t sequence() const { return m_sequence; }
    const modbus::ModbusUrl& url() const { return m_link.url(); }

private:
    modbus::ModbusLink m_link;
    int m_staleAfter_s;
    std::uint16_t m_sequence = 0;
};

}  // namespace driftlab::live
