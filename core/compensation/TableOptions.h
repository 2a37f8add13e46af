#pragma once
// How a table's values are written for a controller: which sign they carry
// and whether each point holds its own value or the change from the previous
// point (docs/compensation.md, "Table options"). The table itself always
// keeps corrections; these say how an exporter turns them into the file.

#include <QString>
#include <optional>

namespace driftlab::compensation {

/// Correction: what the controller adds to the command to reach the target,
/// −deviation. Error: the measured deviation itself, actual − target.
enum class ValueSign { Correction, Error };

/// Absolute: each point's value. Incremental: the change from the previous
/// point (Fanuc's pitch error data); the first point's increment is from 0.
enum class ValueMode { Absolute, Incremental };

/// "correction" / "error", as --sign takes them.
QString signName(ValueSign sign);
/// "absolute" / "incremental", as --values takes them.
QString modeName(ValueMode mode);
std::optional<ValueSign> parseSign(const QString& name);
std::optional<ValueMode> parseMode(const QString& name);

/// `correction_um` turned into the sign `sign` asks for.
inline double signedValue(double correction_um, ValueSign sign) {
    return sign == ValueSign::Correction ? correction_um : -correction_um;
}

}  // namespace driftlab::compensation
