#pragma once
// What a logged value can physically be, per quantity. The reader rejects only
// what cannot be true (and says which unit mix-up it looks like); what is
// merely unusual is left to warnings.

#include <QString>
#include <optional>

#include "core/domain/Channel.h"

namespace driftlab::bundle {

/// Why `value` cannot be a reading of `quantity` in DriftLab's units, or nothing.
/// Temperatures must lie in −60…300 °C, and a reading above 200 °C is taken
/// for kelvin (no part of a feed axis runs that hot; 273–330 K is a lab's
/// range); displacements within ±10 mm (given in µm); speeds within ±200 000 rpm.
/// A room or air sensor (`role` ambient or air) reads at most 45 °C: no
/// machine-tool lab is hotter, and a room logged in °F reads 60–90.
std::optional<QString> impossibleValue(Quantity quantity, double value,
                                       ChannelRole role = ChannelRole::Other);
/// The same for the axis columns of samples.csv (position_mm is checked
/// against the screw instead: see BundleReader).
std::optional<QString> impossibleAxisValue(const QString& column, double value);
/// An interferometer deviation in µm: within ±10 mm.
std::optional<QString> impossibleDeviation(double deviation_um);
/// `count` readings in µm, ten or more, all within ±0.1 µm (`largest_um`):
/// no axis or drift probe is that steady (an interferometer or a probe
/// resolves about 0.001 µm, thermal errors are microns), so they look like mm.
/// Merely unusual: a warning, not an error. `what`: "deviations", "readings
/// of 'D_x'".
std::optional<QString> tinyMicrometres(std::size_t count, double largest_um, const QString& what);
/// A time in s since the run's start: within ±1e7 s (four months).
std::optional<QString> impossibleTime(double time_s);
/// A time as a file gives it, before a logger's clock is taken off (see
/// loggerClockOffset_s): within ±1e10 s, as far as Unix time in seconds goes.
/// The time on the run's clock must then pass impossibleTime.
std::optional<QString> impossibleClockTime(double time_s);

/// A samples.csv header that names its unit, as loggers write it:
/// "T_nut [°C]", "D_z (µm)".
struct HeaderWithUnit {
    QString id, unit;
};
/// The id and the unit of such a header, or nothing when it names none.
std::optional<HeaderWithUnit> splitHeaderUnit(const QString& header);

}  // namespace driftlab::bundle
