#pragma once
// What a logged value can physically be, per quantity. The reader rejects only
// what cannot be true (and says which unit mix-up it looks like); what is
// merely unusual is left to warnings.

#include <QString>
#include <optional>

#include "core/domain/Channel.h"

namespace driftlab {

/// Why `value` cannot be a reading of `quantity` in DriftLab's units, or nothing.
/// Temperatures must lie in −60…300 °C, and a reading above 200 °C is taken
/// for kelvin (no part of a feed axis runs that hot; 273–330 K is a lab's
/// range); displacements within ±10 mm (given in µm); speeds within ±200 000 rpm.
std::optional<QString> impossibleValue(Quantity quantity, double value);
/// The same for the axis columns of samples.csv (position_mm is checked
/// against the screw instead: see BundleReader).
std::optional<QString> impossibleAxisValue(const QString& column, double value);
/// An interferometer deviation in µm: within ±10 mm.
std::optional<QString> impossibleDeviation(double deviation_um);
/// A time in s since the run's start: within ±1e7 s (four months).
std::optional<QString> impossibleTime(double time_s);

}  // namespace driftlab
