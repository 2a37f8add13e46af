#pragma once
// LinuxCNC joint compensation file ([JOINT_n]COMP_FILE, COMP_FILE_TYPE 0 or 1),
// as LinuxCNC 2.9 reads it (docs/compensation.md, "LinuxCNC").

#include "core/compensation/CompensationTable.h"
#include "core/compensation/ExportResult.h"

namespace driftlab::compensation {

/// LinuxCNC keeps at most this many entries per joint (EMCMOT_COMP_SIZE) and
/// reports the excess only on its own console.
constexpr int kLinuxCncMaxRows = 256;

enum class LinuxCncType {
    /// `nominal actual+ actual−`: where the axis really is when commanded to
    /// nominal, approaching upwards / downwards. LinuxCNC takes nominal −
    /// actual as the trim it adds to the motor command.
    Type0,
    /// `nominal trim+ trim−`: what LinuxCNC adds to the motor command.
    Type1,
};

/// One row per point, ascending nominal, machine units mm with 4 decimals
/// (0.1 µm), single spaces, no header, comment or blank line: LinuxCNC
/// stops reading silently at the first line that is not three numbers. A
/// unidirectional table's backlash B̄ is folded into the two columns
/// (trim± = correction ∓ B̄/2) because LinuxCNC ignores [JOINT_n]BACKLASH
/// when a COMP_FILE is given.
ExportResult exportLinuxCnc(const CompensationTable& table, LinuxCncType type);

}  // namespace driftlab::compensation
