#pragma once
// The baselines `auto` must beat on held-out drift (issue 10): plain least
// squares on every temperature rise, and on the best pair of sensors, as a
// test engineer would fit them without DriftLab.

#include <QString>
#include <algorithm>
#include <vector>

#include "core/diagnosis/StretchJackknife.h"
#include "core/models/ModelScore.h"
#include "core/models/ModelValidation.h"
#include "core/models/ThermalErrorData.h"

namespace driftlab::test {

/// The runs as a dataset whose thermal error is the drift channel `target`
/// (a test failure, and no runs, when it cannot be built).
std::vector<models::RunData> driftDataset(const Campaign& c, const QStringList& runs,
                                          const QString& target);

/// A baseline's held-out RMS, and its squares summed per stretch of the
/// held-out runs (the drift's before, the residual's after).
struct HeldOut {
    double rms_um = 0;
    diagnosis::StretchSquares stretches;
};

struct LeastSquaresBaselines {
    HeldOut all_rises;          ///< every usable temperature rise and an offset
    HeldOut best_pair;          ///< the pair with the least training RSS
    QString best_pair_sensors;  ///< "A+B"
    double better_um() const { return std::min(all_rises.rms_um, best_pair.rms_um); }
};

/// Both baselines fitted on `train` and scored on `test`; the sensors are the
/// temperature channels usable in the first training run.
LeastSquaresBaselines leastSquaresBaselines(const std::vector<models::RunData>& train,
                                            const std::vector<models::RunData>& test);

/// What a perfect model scores on `test`: the probe's drift before its noise
/// (`truth_um`: per run, the value at each observation's time, from the run's
/// start), given the same zero as the measurement (the median over the first
/// reference window), against the measured error. Its RMS is the floor the
/// probe's noise sets.
HeldOut perfectModelHeldOut(const std::vector<models::RunData>& test,
                            const std::vector<std::vector<double>>& truth_um,
                            double referenceWindow_s = 60);

/// `auto` fitted on `train` and scored on `test`, beside both baselines.
struct AutoAgainstBaselines {
    models::Score score;          ///< `auto`'s held-out score (error set when it failed)
    QString chosen;               ///< the families `auto` chose, joined by " + "
    std::vector<double> weights;  ///< theirs, in the same order
    LeastSquaresBaselines baselines;
    /// The probability that `auto`'s held-out RMS is below each baseline's
    /// (the smaller of the two): the diagnosis's jackknife over stretches of
    /// the held-out runs, since a drift residual is smooth for many minutes.
    double probability_better = 0;
    /// A perfect model (perfectModelHeldOut) on the same held-out runs, and
    /// the probability that it beats both baselines.
    HeldOut perfect;
    double probability_perfect_better = 0;
    bool beatsBoth() const { return score.rms_um < baselines.better_um(); }
    /// Not better, but within 0.001 µm of the better baseline: a hundredth of
    /// the rig probes' noise, where which one is ahead is the draw's chance.
    bool tiesTheBetter() const {
        return !beatsBoth() && score.rms_um < baselines.better_um() + 0.001;
    }
    bool perfectSurelyBeatsBoth() const { return probability_perfect_better > 0.95; }
    /// The share of the held-out readings inside `auto`'s prediction interval.
    models::Coverage coverage;
    /// The figures, for a failure message.
    QString text() const;
};

/// The comparison, with the `perfect` model beside it; a failed fit is a
/// test failure naming `label`.
AutoAgainstBaselines autoAgainstBaselines(const std::vector<models::RunData>& train,
                                          const std::vector<models::RunData>& test,
                                          const QString& label, HeldOut perfect);

/// How often `auto` beats both baselines, and how often the held-out
/// difference is beyond chance (P > 0.95 either way).
struct AutoAgainstBaselinesTally {
    int cases = 0, beaten = 0, surely_better = 0, surely_worse = 0;
    /// Probes where a perfect model beats both baselines beyond chance, and
    /// where `auto` beats both of them there.
    int perfect_beats = 0, beaten_where_perfect_beats = 0;
    /// Ties (tiesTheBetter), overall and where a perfect model beats both.
    int tied = 0, tied_where_perfect_beats = 0;
    void add(const AutoAgainstBaselines& a);
    /// The counts, for a failure message.
    QString text() const;
};

}  // namespace driftlab::test
