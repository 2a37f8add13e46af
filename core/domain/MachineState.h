#pragma once
// What the machine is doing, as its controller reports it. A compensation
// table or a live offset changes only when the machine is not cutting: a
// correction that moves the tool mid-cut marks the workpiece (docs/compensation.md).

#include <QString>

namespace driftlab {

/// The numbering is the Modbus register map's (docs/modbus-register-map.md).
enum class MachineState { Idle = 0, Moving = 1, Cutting = 2, ToolChange = 3 };

/// Idle, moving without cutting and tool change are safe moments to change
/// a correction; cutting is not.
constexpr bool isSafeToCompensate(MachineState state) {
    return state != MachineState::Cutting;
}

inline QString machineStateName(MachineState state) {
    switch (state) {
        case MachineState::Idle:
            return QStringLiteral("idle");
        case MachineState::Moving:
            return QStringLiteral("moving");
        case MachineState::Cutting:
            return QStringLiteral("cutting");
        case MachineState::ToolChange:
            return QStringLiteral("tool change");
    }
    return QStringLiteral("state %1").arg(int(state));
}

}  // namespace driftlab
