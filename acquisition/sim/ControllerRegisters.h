#pragma once
// What a controller does with DriftLab's register map
// (docs/modbus-register-map.md), apart from the transport: checks a committed
// table (capacity, checksum), applies it when the machine is not cutting,
// keeps the previous table for a rollback, and the faults a test injects.

#include <cstdint>
#include <vector>

#include "acquisition/devices/AxisStateRegisters.h"
#include "acquisition/push/CompensationRegisterMap.h"

namespace driftlab::sim {

/// Faults the simulated controller injects, each once unless said otherwise.
struct ControllerFaults {
    /// Closes the connection instead of answering the write request that
    /// follows N more write requests (counted from when the faults are set);
    /// -1: never.
    int drop_after_writes = -1;
    /// Answers every commit with "refused".
    bool refuse_commit = false;
    /// Changes one data register of the active table right after applying.
    bool corrupt_after_apply = false;
    /// With the machine cutting: the cut ends (state idle) after the commit
    /// status has been read this many times while a commit waits; 0: the
    /// machine stays cutting ("stuck").
    int idle_after_polls = 0;
};

class ControllerRegisters {
public:
    /// Registers 0 … kRegisterCount-1, one holding-register space.
    static constexpr int kRegisterCount = push::reg::kLiveFirst + push::reg::kLiveCount;

    /// `registers` (kRegisterCount values) are shared with the transport.
    ControllerRegisters(std::uint16_t* registers, int capacity, MachineState state,
                        ControllerFaults faults);

    /// Whether a client may write [address, address + count): the staged table,
    /// the command and the live-offset registers DriftLab writes, nothing else.
    bool writable(int address, int count) const;
    /// Counts a write request; true when the drop fault says to close the
    /// connection instead of answering it.
    bool dropThisWrite();
    /// After a write was stored: acts on a command.
    void afterWrite(int address, int count);
    /// Before a read is answered: counts commit-status polls (idle_after_polls).
    void beforeRead(int address, int count);
    /// One scan of the controller: applies a committed table when safe.
    void scan();

    void setMachineState(MachineState state);
    /// Registers 9…13; the simulated controller always reports (register 8 is 1).
    void setAxisState(const devices::AxisState& state);
    void setFaults(ControllerFaults faults);
    int writeRequests() const { return m_writes; }
    int applied() const { return m_applied; }
    push::TableImage active() const;

private:
    void commit();
    void abort();
    void rollBack();
    void apply();
    push::TableImage image(int headerAddress, int dataAddress) const;
    void store(const push::TableImage& image, int headerAddress, int dataAddress);
    void setStatus(push::CommitStatus status, std::uint16_t version);

    std::uint16_t* m_regs;
    int m_capacity;
    ControllerFaults m_faults;
    bool m_pending = false;
    push::TableImage m_previous;  ///< what a rollback restores (version 0: no table)
    int m_writes = 0;
    int m_dropAt = -1;  ///< the write request number the drop fault closes on
    int m_polls = 0;
    int m_applied = 0;
};

}  // namespace driftlab::sim
