#pragma once
// The numbers of a procedure a test engineer changes most (sample interval,
// warm-up, cool-down, targets, cycles), per kind, as getters and setters on
// the procedure; everything else is edited in the procedure's JSON.

#include <QString>
#include <functional>
#include <vector>

#include "core/procedures/Procedure.h"

namespace driftlab::ui {

struct ProcedureKeyNumber {
    QString label;  ///< with its unit
    QString key;    ///< the key path as docs/procedures.md names it
    int decimals = 0;
    std::function<double(const procedures::Procedure&)> get;
    /// Sets the value (for a moving-state sequence: in every state).
    std::function<void(procedures::Procedure&, double)> set;
};

/// The key numbers of a procedure of `kind`, the sample interval first.
std::vector<ProcedureKeyNumber> keyNumbersOf(procedures::ProcedureKind kind);

/// "2 h 05 min", "45 s": a duration as a test engineer reads it.
QString readableDuration(double seconds);

}  // namespace driftlab::ui
