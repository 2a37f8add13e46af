#pragma once
// A number in a message as the user wrote it: a value read from a file or
// typed in comes back digit for digit (up to 12 significant digits), with no
// trailing zeros and no locale. One formatter for every error and note, so the
// same value never reads two ways.

#include <QString>

namespace driftlab {

inline QString numberText(double value) {
    return QString::number(value, 'g', 12);
}

}  // namespace driftlab
