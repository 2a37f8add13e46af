#pragma once
// Where a run leaves the temperatures its model was fitted on. A regression
// on temperature rises is an interpolation: on a run whose rises go beyond
// the training runs' its prediction is an extrapolation, and the held-out
// score of a model that mistook one input for another shows it only there.
// The case that shows it: training runs that all warmed the room with the
// machine, so that a few sensors stand in for the room, then a run in a
// cooling room (docs/models.md §3, "Beyond the training runs").

#include <QString>
#include <QStringList>
#include <vector>

#include "core/models/ThermalErrorData.h"

namespace driftlab::models {

/// One channel of one run whose rise leaves the training runs' range.
struct RiseBeyondTraining {
    QString run;
    QString channel;
    ChannelRole role = ChannelRole::Other;
    double rise_K = 0;           ///< the run's rise furthest outside the range
    double training_low_K = 0;   ///< the lowest rise of any training run
    double training_high_K = 0;  ///< the highest
};

/// How far outside the range a rise must reach to be reported: the larger of
/// an absolute floor (a thermometer's few hundredths of a kelvin of noise and
/// its reference taken from a minute of samples stay well within it) and a
/// share of the training range.
struct TrainingEnvelopeOptions {
    double min_margin_K = 0.1;
    double margin_of_range = 0.1;
};

/// Every usable temperature channel of each run in `runs` whose rise goes
/// beyond the training runs' lowest or highest rise by more than the margin;
/// a channel the training runs cannot give is left out. Ordered by run, then
/// by how far beyond the range (in ranges), furthest first.
std::vector<RiseBeyondTraining> risesBeyondTraining(const std::vector<RunData>& training,
                                                    const std::vector<RunData>& runs,
                                                    const TrainingEnvelopeOptions& options = {});

/// One line per run: "P4: TC15 (ambient) −0.88 K (training runs −0.02 … +1.16 K), …".
QStringList describeRisesBeyondTraining(const std::vector<RiseBeyondTraining>& beyond);

/// A run whose spindle speed leaves the training runs' range: the heat input
/// of a spindle's drift, which no thermometer need show (a probe near the
/// spindle nose warms before any sensor on the housing does).
struct SpeedBeyondTraining {
    QString run;
    QString channel;
    double speed_rpm = 0;  ///< the run's speed furthest outside the range
    double training_low_rpm = 0, training_high_rpm = 0;
};

/// Every run of `runs` whose spindle speed goes beyond the lowest or highest
/// speed of the training runs by more than max(10 rpm, a tenth of that
/// range); none where a training run logs no speed.
std::vector<SpeedBeyondTraining> speedsBeyondTraining(const std::vector<RunData>& training,
                                                      const std::vector<RunData>& runs);

/// One line per run: "R5000: S (spindle speed) 5000 rpm (training runs 0 … 3750 rpm)".
QStringList describeSpeedsBeyondTraining(const std::vector<SpeedBeyondTraining>& beyond);

}  // namespace driftlab::models
