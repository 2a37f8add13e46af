#pragma once
// Golden data sets of the ISO 230-2 tests, with their values worked by hand.
// tests/iso/data/golden_3x5.csv holds the same readings as `golden3x5()` for
// the CLI tests.

#include <vector>

#include "core/iso/Iso230_2.h"

namespace driftlab::iso::test {

/// The warnings of an evaluation but those of the standard's minimums (five
/// targets, five approaches), which the small hand-worked sets fall short of.
inline QStringList withoutMinimums(const QStringList& warnings) {
    QStringList kept;
    for (const QString& w : warnings)
        if (!w.startsWith(QStringLiteral("below ISO 230-2's minimum: "))) kept << w;
    return kept;
}

/// Readings of one target and direction, one per cycle, cycles 1, 2, ...
inline void add(std::vector<Reading>& readings, double target_mm, Direction direction,
                std::vector<double> deviations_um) {
    int cycle = 1;
    for (double d : deviations_um) readings.push_back({target_mm, direction, cycle++, d});
}

/// G1: 3 targets × 5 cycles × 2 directions, k = 2. Every series is
/// x̄ + (−a, +a, 0, +a, −a) over cycles 1..5: its mean is x̄ exactly, its
/// sum of squares 4a², so s = sqrt(4a² / (5 − 1)) = a exactly, and its
/// trend over the cycles is zero (−2·−a − 1·a + 0 + 1·a + 2·−a = 0): no drift.
///
///   target   ↑ readings (µm)          x̄↑  s↑   ↓ readings (µm)           x̄↓  s↓
///   0 mm     2, 4, 3, 4, 2            3   1    −3, −1, −2, −1, −3        −2  1
///   100 mm   3.5, 4.5, 4, 4.5, 3.5    4   0.5  1.5, 4.5, 3, 4.5, 1.5     3   1.5
///   200 mm   −1, −1, −1, −1, −1       −1  0    −5, −3, −4, −3, −5        −4  1
///   (sums: 15/5 = 3, −10/5 = −2, 20/5 = 4, 15/5 = 3, −5/5 = −1, −20/5 = −4)
///
///   per target     B_i = x̄↑−x̄↓  R↑_i = 4s↑  R↓_i = 4s↓  2s↑+2s↓+|B_i|  R_i  x̄_i
///   0 mm           3−(−2) = 5     4           4           2+2+5 = 9      9    0.5
///   100 mm         4−3 = 1        2           6           1+3+1 = 5      6    3.5
///   200 mm         −1−(−4) = 3    0           4           0+2+3 = 5      5    −2.5
///
///   axis: B = 5 (largest |B_i|), B̄ = (5+1+3)/3 = 3,
///         R↑ = max(4, 2, 0) = 4, R↓ = max(4, 6, 4) = 6, R = max(9, 6, 5) = 9
///           (at 0 mm the bidirectional term 9 beats R↑_i = R↓_i = 4, and the
///           axis R = 9 beats max(R↑, R↓) = 6; at 100 mm R_i is the backward R↓_i),
///         E↑ = 4 − (−1) = 5, E↓ = 3 − (−4) = 7,
///         E = max(3, 4, −1, −2, 3, −4) − min(...) = 4 − (−4) = 8 (≠ E↑, ≠ E↓:
///           its maximum is a ↑ mean, its minimum a ↓ mean),
///         M = 3.5 − (−2.5) = 6,
///         A↑ = max(3+2, 4+1, −1+0) − min(3−2, 4−1, −1−0) = 5 − (−1) = 6,
///         A↓ = max(−2+2, 3+3, −4+2) − min(−2−2, 3−3, −4−2) = 6 − (−6) = 12,
///         A = max(5, 5, −1, 0, 6, −2) − min(1, 3, −1, −4, 0, −6) = 6 − (−6) = 12.
inline std::vector<Reading> golden3x5() {
    std::vector<Reading> r;
    add(r, 0, Direction::Positive, {2, 4, 3, 4, 2});
    add(r, 0, Direction::Negative, {-3, -1, -2, -1, -3});
    add(r, 100, Direction::Positive, {3.5, 4.5, 4, 4.5, 3.5});
    add(r, 100, Direction::Negative, {1.5, 4.5, 3, 4.5, 1.5});
    add(r, 200, Direction::Positive, {-1, -1, -1, -1, -1});
    add(r, 200, Direction::Negative, {-5, -3, -4, -3, -5});
    return r;
}

/// G2: an axis of 2500 mm measured with one approach per direction per target
/// (allowed over 2000 mm): only the values without s are determined.
///
///   target    ↑   ↓    B_i = ↑ − ↓   x̄_i
///   0 mm      1   −1   2             0
///   1250 mm   3   4    −1            3.5
///   2500 mm   4   2    2             3
///
///   B = 2 (largest |B_i|, first at 0 mm), B̄ = (2 − 1 + 2)/3 = 1,
///   E↑ = 4 − 1 = 3, E↓ = 4 − (−1) = 5, E = max(1,3,4,−1,4,2) − min(...) = 4 − (−1) = 5,
///   M = 3.5 − 0 = 3.5; s, R and A are not determined.
inline std::vector<Reading> longAxisSingleApproach() {
    std::vector<Reading> r;
    add(r, 0, Direction::Positive, {1});
    add(r, 0, Direction::Negative, {-1});
    add(r, 1250, Direction::Positive, {3});
    add(r, 1250, Direction::Negative, {4});
    add(r, 2500, Direction::Positive, {4});
    add(r, 2500, Direction::Negative, {2});
    return r;
}

}  // namespace driftlab::iso::test
