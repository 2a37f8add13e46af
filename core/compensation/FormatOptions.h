#pragma once
// Which table options each controller format can hold: the sign of its
// values, absolute or incremental values, combined or per-direction columns.
// The first sign and mode listed are the controller's own convention, the
// default when none is asked for (docs/compensation.md, "Table options").

#include <QString>
#include <optional>
#include <vector>

#include "core/compensation/TableOptions.h"

namespace driftlab::compensation {

struct FormatOptions {
    std::vector<ValueSign> signs;  ///< what the file can hold; signs[0] is the format's own
    std::vector<ValueMode> modes;  ///< modes[0] is the format's own
    bool per_direction = false;    ///< separate + and − columns
    /// Why the format holds what it does, named when an option is refused.
    QString sign_reason;
    QString mode_reason;
    QString direction_reason;
};

/// The options of one of tableFormats(); empty lists for an unknown format.
FormatOptions formatOptions(const QString& format);

/// The sign and mode `format` writes when asked for `sign` and `mode`
/// (unset: its own).
ValueSign effectiveSign(const QString& format, std::optional<ValueSign> sign);
ValueMode effectiveMode(const QString& format, std::optional<ValueMode> mode);

/// Empty when `format` can hold the options; otherwise one sentence naming
/// the option, the format and why ("--sign correction: Sinumerik's ...").
QString checkFormatOptions(const QString& format, std::optional<ValueSign> sign,
                           std::optional<ValueMode> mode, bool bidirectional);

}  // namespace driftlab::compensation
