#pragma once
// The format's fixed columns (docs/bundles.md: run, time_s, target_mm,
// deviation_um, feed_mm_min, …) as other software spells them in a header:
// in another case ("Time_s", "RUN") or with the unit in brackets or
// parentheses, as loggers and laser packages write it ("time [s]",
// "Deviation (µm)", "feed [mm/min]", "torque [N·m]"). Channel ids are the
// campaign's own free text and are not matched so.

#include <QString>
#include <optional>

namespace driftlab::bundle {

/// Whether `header` names the column `name` (a format column: a stem and,
/// after its first '_', a unit).
bool spellsColumn(const QString& header, const QString& name);

/// When `header` names the quantity of `name` in another unit ("time [ms]"
/// or "time_ms" for time_s) or without one ("time"): that unit as written
/// ("ms"; empty for none).
std::optional<QString> otherUnitOf(const QString& header, const QString& name);

}  // namespace driftlab::bundle
