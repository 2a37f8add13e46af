#pragma once
// The one rule for a unit a file declares for a channel's values (a bundle's
// samples.csv header, a device map's "unit"): DriftLab's own unit of the
// quantity (°C, µm, rpm) in any of its spellings is taken as it is, a
// temperature in °F or K is converted to °C, and anything else is refused,
// because a value read in the wrong unit still looks like a reading.

#include <QString>
#include <optional>

#include "core/domain/Channel.h"

namespace driftlab {

/// How a value in a declared unit becomes one in unitOf(quantity):
/// (value − zero) · numerator / denominator, in that order, so that DriftLab's
/// own unit comes back bit for bit and °F is the exact (°F − 32) · 5 / 9.
struct UnitConversion {
    QString from;            ///< the declared unit, as written
    double zero = 0.0;       ///< the declared unit's value at DriftLab's zero (32 °F, 273.15 K)
    double numerator = 1.0;  ///< DriftLab's units per `denominator` declared units
    double denominator = 1.0;

    double apply(double value) const { return (value - zero) * numerator / denominator; }
    bool isIdentity() const { return zero == 0.0 && numerator == denominator; }
};

/// The conversion of values in `unit` to DriftLab's unit of `quantity`, or
/// nullopt with `why` naming the unit and the units DriftLab reads.
std::optional<UnitConversion> conversionToDriftLabUnit(Quantity quantity, const QString& unit,
                                                       QString* why);

}  // namespace driftlab
