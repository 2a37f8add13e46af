#pragma once
// How far a held-out gain can be trusted: the gain (1 − RMS after / RMS
// before) is recomputed with each stretch of the held-out runs left out in
// turn (the delete-one jackknife, Efron & Stein 1981), and its spread gives
// the probability that it is above zero or above another candidate's gain on
// the same stretches. Stretches, not readings: a thermal residual is smooth
// for many minutes, so neighbouring readings are not independent evidence.

#include <QString>
#include <vector>

#include "core/models/HeatTransferModel.h"

namespace driftlab::diagnosis {

/// Each held-out run's time span is cut into this many equal stretches.
constexpr int kStretchesPerRun = 10;

/// Sums of squares of one quantity per stretch, before and after an extension:
/// stretch k of run r is at r·perRun + k, the same for every quantity.
struct StretchSquares {
    std::vector<double> before, after;
};

/// The stretch (0 … perRun − 1) of a reading at `time_s` in a run spanning
/// [first_s, last_s]; readings outside it count to the nearest end.
int stretchOf(double time_s, double first_s, double last_s, int perRun = kStretchesPerRun);

/// Of the positioning error (`channel` empty) or one sensor's residual.
/// `before` and `after` hold the same runs in the same order.
StretchSquares stretchSquares(const std::vector<models::ReadingResiduals>& before,
                              const std::vector<models::ReadingResiduals>& after,
                              const QString& channel, int perRun = kStretchesPerRun);

/// P(T ≤ t) for Student's t with `dof` degrees of freedom.
double studentTCdf(double t, double dof);

/// The probability that the gain of `a` is larger than that of `b` (or than
/// zero when `b` is null): the difference over its jackknife standard error,
/// read on Student's t with (stretches − 1) degrees of freedom.
double probabilityLarger(const StretchSquares& a, const StretchSquares* b);

}  // namespace driftlab::diagnosis
