#include "acquisition/sim/ControllerRegisters.h"

#include <algorithm>

namespace driftlab::sim {

// The register map this simulated controller serves is the push's own.
using namespace push;

ControllerRegisters::ControllerRegisters(std::uint16_t* registers, int capacity, MachineState state,
                                         ControllerFaults faults)
    : m_regs(registers), m_capacity(capacity) {
    setFaults(faults);
    std::fill(m_regs, m_regs + kRegisterCount, 0);
    m_regs[push::reg::kMagic] = kMagicValue;
    m_regs[push::reg::kMapVersion] = kMapVersionValue;
    m_regs[push::reg::kCapacity] = std::uint16_t(capacity);
    m_regs[push::reg::kAxisReport] = 1;
    setMachineState(state);
}

bool ControllerRegisters::writable(int address, int count) const {
    const auto inside = [&](int first, int n) {
        return address >= first && address + count <= first + n;
    };
    return inside(push::reg::kStagedHeader, kHeaderCount + 1) ||
           inside(push::reg::kStagedData, 2 * m_capacity) ||
           inside(push::reg::kLiveFirst,
                  push::reg::kLiveCount - 1);  // 2005 live_stale is the controller's
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
    if (address > push::reg::kCommand || address + count <= push::reg::kCommand) return;
    const auto command = push::Command(m_regs[push::reg::kCommand]);
    m_regs[push::reg::kCommand] = 0;  // done; a read shows no command waiting
    switch (command) {
        case push::Command::Commit:
            commit();
            break;
        case push::Command::Abort:
            abort();
            break;
        case push::Command::RollBack:
            rollBack();
            break;
    }
}

void ControllerRegisters::beforeRead(int address, int count) {
    const bool statusPolled =
        address <= push::reg::kCommitStatus && address + count > push::reg::kCommitStatus;
    if (!statusPolled || !m_pending || m_faults.idle_after_polls <= 0) return;
    if (++m_polls >= m_faults.idle_after_polls) {
        setMachineState(MachineState::Idle);
        scan();
    }
}

void ControllerRegisters::scan() {
    if (m_pending && MachineState(m_regs[push::reg::kMachineState]) != MachineState::Cutting)
        apply();
}

void ControllerRegisters::setMachineState(MachineState state) {
    m_regs[push::reg::kMachineState] = std::uint16_t(state);
}

void ControllerRegisters::setAxisState(const devices::AxisState& state) {
    const devices::AxisStateWords words = devices::encodeAxisState(state);
    std::copy(words.begin(), words.end(), m_regs + push::reg::kAxisPosition);
}

push::TableImage ControllerRegisters::active() const {
    return image(push::reg::kActiveHeader, push::reg::kActiveData);
}

push::TableImage ControllerRegisters::image(int headerAddress, int dataAddress) const {
    push::TableImage out;
    std::copy_n(m_regs + headerAddress, kHeaderCount, out.header.begin());
    const int points = std::clamp(out.points(), 0, m_capacity);
    out.plus.assign(m_regs + dataAddress, m_regs + dataAddress + points);
    if (out.bidirectional())
        out.minus.assign(m_regs + dataAddress + m_capacity,
                         m_regs + dataAddress + m_capacity + points);
    return out;
}

void ControllerRegisters::store(const push::TableImage& table, int headerAddress, int dataAddress) {
    std::fill(m_regs + headerAddress, m_regs + headerAddress + kHeaderCount, 0);
    std::fill(m_regs + dataAddress, m_regs + dataAddress + 2 * m_capacity, 0);
    std::copy(table.header.begin(), table.header.end(), m_regs + headerAddress);
    std::copy(table.plus.begin(), table.plus.end(), m_regs + dataAddress);
    std::copy(table.minus.begin(), table.minus.end(), m_regs + dataAddress + m_capacity);
}

void ControllerRegisters::setStatus(push::CommitStatus status, std::uint16_t version) {
    m_regs[push::reg::kCommitStatus] = std::uint16_t(status);
    m_regs[push::reg::kAckVersion] = version;
}

void ControllerRegisters::commit() {
    const push::TableImage staged = image(push::reg::kStagedHeader, push::reg::kStagedData);
    m_pending = false;
    m_polls = 0;
    const bool fits = staged.version() != 0 && staged.points() >= 2 &&
                      staged.points() <= m_capacity && staged.spacing_um() > 0;
    if (!fits || m_faults.refuse_commit)
        return setStatus(push::CommitStatus::Refused, staged.version());
    if (staged.computeChecksum() != staged.checksum())
        return setStatus(push::CommitStatus::ChecksumMismatch, staged.version());
    m_pending = true;
    setStatus(push::CommitStatus::Staged, staged.version());
    scan();
}

void ControllerRegisters::abort() {
    if (m_pending) setStatus(push::CommitStatus::Aborted, m_regs[push::reg::kStagedHeader]);
    m_pending = false;
    store(push::TableImage{}, push::reg::kStagedHeader, push::reg::kStagedData);
}

void ControllerRegisters::rollBack() {
    const std::uint16_t undone = m_regs[push::reg::kActiveVersion];
    store(m_previous, push::reg::kActiveHeader, push::reg::kActiveData);
    m_regs[push::reg::kActiveVersion] = m_previous.version();
    m_previous = push::TableImage{};
    m_regs[push::reg::kPreviousVersion] = 0;
    setStatus(push::CommitStatus::RolledBack, undone);
}

void ControllerRegisters::apply() {
    // One step of the scan: the active table becomes the previous one and the
    // staged one the active one.
    const push::TableImage staged = image(push::reg::kStagedHeader, push::reg::kStagedData);
    m_previous = active();
    store(staged, push::reg::kActiveHeader, push::reg::kActiveData);
    m_regs[push::reg::kPreviousVersion] = m_previous.version();
    m_regs[push::reg::kActiveVersion] = staged.version();
    m_pending = false;
    ++m_applied;
    setStatus(push::CommitStatus::Applied, staged.version());
    if (m_faults.corrupt_after_apply) {
        m_faults.corrupt_after_apply = false;
        m_regs[push::reg::kActiveData + staged.points() / 2] ^= 0x0010;
    }
}

}  // namespace driftlab::sim
