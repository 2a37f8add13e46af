#pragma once
// The baselines `auto` must beat on held-out drift (issue 10): plain least
// squares on every temperature rise, and on the best pair of sensors, as a
// test engineer would fit them without DriftLab.

#include <QString>
#include <algorithm>
#include <vector>

#include "core/models/ModelScore.h"
#include "core/models/ThermalErrorData.h"

namespace driftlab::test {

/// The runs as a dataset whose thermal error is the drift channel `target`
/// (a test failure, and no runs, when it cannot be built).
std::vector<models::RunData> driftDataset(const Campaign& c, const QStringList& runs,
                                          const QString& target);

struct LeastSquaresBaselines {
    double all_rises_um = 0;  ///< held-out RMS, every usable temperature rise and an offset
    double best_pair_um = 0;  ///< held-out RMS of the pair with the least training RSS
    QString best_pair;        ///< "A+B"
    double better_um() const { return std::min(all_rises_um, best_pair_um); }
};

/// Both baselines fitted on `train` and scored on `test`; the sensors are the
/// temperature channels usable in the first training run.
LeastSquaresBaselines leastSquaresBaselines(const std::vector<models::RunData>& train,
                                            const std::vector<models::RunData>& test);

/// `auto` fitted on `train` and scored on `test`, beside both baselines.
struct AutoAgainstBaselines {
    models::Score score;  ///< `auto`'s held-out score (error set when it failed)
    QString chosen;       ///< the family `auto` chose
    LeastSquaresBaselines baselines;
    bool beatsBoth() const { return score.rms_um < baselines.better_um(); }
};

/// The comparison, printed as one row labelled `label` of the table that
/// printAutoAgainstBaselinesHeader() heads; a failed fit is a test failure.
AutoAgainstBaselines autoAgainstBaselines(const std::vector<models::RunData>& train,
                                          const std::vector<models::RunData>& test,
                                          const QString& label);
void printAutoAgainstBaselinesHeader();

}  // namespace driftlab::test
