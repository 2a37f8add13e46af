#pragma once
// The hand-checked table of the compensation tests: ISO 230-2's golden data
// set G1 (tests/iso/Iso230TestData.h) laid out every 50 mm.
//
//   target   x̄↑    x̄↓    x̄ = (x̄↑ + x̄↓)/2      B̄ = (5 + 1 + 3)/3 = 3 µm
//   0 mm     3     −2    0.5
//   100 mm   4     3     3.5
//   200 mm   −1    −4    −2.5
//
// Every 50 mm, interpolated linearly, correction = −deviation (µm):
//   position    −x̄      −x̄↑     −x̄↓
//   0           −0.5    −3      2
//   50          −2.0    −3.5    −0.5     (midway: −(0.5 + 3.5)/2, −(3 + 4)/2, −(−2 + 3)/2)
//   100         −3.5    −4      −3
//   150         −0.5    −1.5    0.5      (midway: −(3.5 − 2.5)/2, −(4 − 1)/2, −(3 − 4)/2)
//   200         2.5     1       4
//
// The expanded uncertainty of each point (k = 2, five cycles): of x̄,
// 2·½·√(s↑²/5 + s↓²/5); of a bidirectional column, 2·max(s↑, s↓)/√5:
//   target   s↑    s↓    unidirectional        bidirectional
//   0 mm     1     1     √(2/5) = 0.632        2/√5 = 0.894
//   100 mm   0.5   1.5   √(2.5/5) = 0.707      3/√5 = 1.342
//   200 mm   0     1     √(1/5) = 0.447        2/√5 = 0.894
// and midway at 50 and 150 mm: 0.670, 0.577 and 1.118, 1.118.

#include "core/compensation/CompensationTable.h"
#include "tests/iso/Iso230TestData.h"

namespace driftlab::compensation::test {

inline TableResult golden50mm(bool bidirectional) {
    TableSettings settings;
    settings.spacing_mm = 50;
    settings.bidirectional = bidirectional;
    return buildTable(iso::evaluate(iso::test::golden3x5()), settings);
}

/// A table written by hand: one point per entry, both columns alike.
inline CompensationTable handTable(std::vector<double> position_mm,
                                   std::vector<double> correction_um) {
    CompensationTable table;
    table.position_mm = std::move(position_mm);
    table.correction_plus_um = correction_um;
    table.correction_minus_um = std::move(correction_um);
    return table;
}

}  // namespace driftlab::compensation::test
