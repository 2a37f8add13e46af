#include "acquisition/sim/ControllerRegisters.h"

#include <algorithm>

namespace driftlab::push {

ControllerRegisters::ControllerRegisters(std::uint16_t* registers, int capacity, MachineState state,
                                         ControllerFaults faults)
    : m_regs(registers), m_capacity(capacity) {
    setFaults(faults);
    std::fill(m_regs, m_regs + kRegisterCount, 0);
    m_regs[reg::kMagic] = kMagicValue;
    m_regs[reg::kMapVersion] = kMapVersionValue;
    m_regs[reg::kCapacity] = std::uint16_t(capacity);
    m_regs[reg::kAxisReport] = 1;
    setMachineState(state);
}

bool ControllerRegisters::writable(int address, int count) const {
    const auto inside = [&](int first, int n) {
        return address >= first && address + count <= first + n;
    };
    return inside(reg::kStagedHeader, kHeaderCount + 1) ||
           inside(reg::kStagedData, 2 * m_capacity) ||
           inside(reg::kLiveFirst, reg::kLiveCount - 1);  // 2005 live_stale is the controller's
}

void ControllerRegisters::setFaults(ControllerFaults faults) {
    m_faults = faults;
    m_dropAt = faults.drop_after_writes < 0 ? -1 : m_writes + faults.drop_after_writes + 1;
}

bool ControllerRegisters::dropThisWrite() {
    if (++m_writes != m_dropAt) return false;
    m_dropAt = -1;
    return true;
}

void ControllerRegisters::afterWrite(int address, int count) {
    if (address > reg::kCommand || address + count <= reg::kCommand) return;
    const auto command = Command(m_regs[reg::kCommand]);
    m_regs[reg::kCommand] = 0;  // done; a read shows no command waiting
    switch (command) {
        case Command::Commit:
            commit();
            break;
        case Command::Abort:
            abort();
            break;
        case Command::RollBack:
            rollBack();
            break;
    }
}

void ControllerRegisters::beforeRead(int address, int count) {
    const bool statusPolled = address <= reg::kCommitStatus && address + count > reg::kCommitStatus;
    if (!statusPolled || !m_pending || m_faults.idle_after_polls <= 0) return;
    if (++m_polls >= m_faults.idle_after_polls) {
        setMachineState(MachineState::Idle);
        scan();
    }
}

void ControllerRegisters::scan() {
    if (m_pending && MachineState(m_regs[reg::kMachineState]) != MachineState::Cutting) apply();
}

void ControllerRegisters::setMachineState(MachineState state) {
    m_regs[reg::kMachineState] = std::uint16_t(state);
}

void ControllerRegisters::setAxisState(const devices::AxisState& state) {
    const devices::AxisStateWords words = devices::encodeAxisState(state);
    std::copy(words.begin(), words.end(), m_regs + reg::kAxisPosition);
}

TableImage ControllerRegisters::active() const {
    return image(reg::kActiveHeader, reg::kActiveData);
}

TableImage ControllerRegisters::image(int headerAddress, int dataAddress) const {
    TableImage out;
    std::copy_n(m_regs + headerAddress, kHeaderCount, out.header.begin());
    const int points = std::clamp(out.points(), 0, m_capacity);
    out.plus.assign(m_regs + dataAddress, m_regs + dataAddress + points);
    if (out.bidirectional())
        out.minus.assign(m_regs + dataAddress + m_capacity,
                         m_regs + dataAddress + m_capacity + points);
    return out;
}

void ControllerRegisters::store(const TableImage& table, int headerAddress, int dataAddress) {
    std::fill(m_regs + headerAddress, m_regs + headerAddress + kHeaderCount, 0);
    std::fill(m_regs + dataAddress, m_regs + dataAddress + 2 * m_capacity, 0);
    std::copy(table.header.begin(), table.header.end(), m_regs + headerAddress);
    std::copy(table.plus.begin(), table.plus.end(), m_regs + dataAddress);
    std::copy(table.minus.begin(), table.minus.end(), m_regs + dataAddress + m_capacity);
}

void ControllerRegisters::setStatus(CommitStatus status, std::uint16_t version) {
    m_regs[reg::kCommitStatus] = std::uint16_t(status);
    m_regs[reg::kAckVersion] = version;
}

void ControllerRegisters::commit() {
    const TableImage staged = image(reg::kStagedHeader, reg::kStagedData);
    m_pending = false;
    m_polls = 0;
    const bool fits = staged.version() != 0 && staged.points() >= 2 &&
                      staged.points() <= m_capacity && staged.spacing_um() > 0;
    if (!fits || m_faults.refuse_commit) return setStatus(CommitStatus::Refused, staged.version());
    if (staged.computeChecksum() != staged.checksum())
        return setStatus(CommitStatus::ChecksumMismatch, staged.version());
    m_pending = true;
    setStatus(CommitStatus::Staged, staged.version());
    scan();
}

void ControllerRegisters::abort() {
    if (m_pending) setStatus(CommitStatus::Aborted, m_regs[reg::kStagedHeader]);
    m_pending = false;
    store(TableImage{}, reg::kStagedHeader, reg::kStagedData);
}

void ControllerRegisters::rollBack() {
    const std::uint16_t undone = m_regs[reg::kActiveVersion];
    store(m_previous, reg::kActiveHeader, reg::kActiveData);
    m_regs[reg::kActiveVersion] = m_previous.version();
    m_previous = TableImage{};
    m_regs[reg::kPreviousVersion] = 0;
    setStatus(CommitStatus::RolledBack, undone);
}

void ControllerRegisters::apply() {
    // One step of the scan: the active table becomes the previous one and the
    // staged one the active one.
    const TableImage staged = image(reg::kStagedHeader, reg::kStagedData);
    m_previous = active();
    store(staged, reg::kActiveHeader, reg::kActiveData);
    m_regs[reg::kPreviousVersion] = m_previous.version();
    m_regs[reg::kActiveVersion] = staged.version();
    m_pending = false;
    ++m_applied;
    setStatus(CommitStatus::Applied, staged.version());
    if (m_faults.corrupt_after_apply) {
        m_faults.corrupt_after_apply = false;
        m_regs[reg::kActiveData + staged.points() / 2] ^= 0x0010;
    }
}

}  // namespace driftlab::push
