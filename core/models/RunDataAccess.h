#pragma once
// Reading a run's data at the points a model is evaluated. Every helper throws
// ModelError naming the run and the channel when the data cannot give a value,
// so a model never silently fits or predicts from a hole in the data.

#include <Eigen/Core>
#include <QString>
#include <QStringList>
#include <functional>
#include <vector>

#include "core/models/ThermalErrorData.h"

namespace driftlab::models {

/// "channel 'T_nut'" or "column 'torque_Nm'", for messages.
QString describeSignal(const Signal& signal);

/// Linear interpolation at `time_s`, held flat up to the signal's gap limit
/// (Signal::gapLimit_s of the run's `max_gap_s`) beyond the first and last
/// samples; a longer gap around the time is an error.
double valueAt(const Signal& signal, double time_s, double max_gap_s, const QString& runId);

/// Requires samples from the run's start to `until_s` with no gap longer than
/// the signal's gap limit (a held signal must not be held across a hole).
void requireCoverage(const RunData& run, const Signal& signal, double until_s);

/// Temperature rises (rows: points, columns: channels) of the channels at the points.
Eigen::MatrixXd risesAt(const RunData& run, const QStringList& channelIds,
                        const std::vector<PredictionPoint>& at);

/// Temperature channels without a single sample in some of the runs (a spindle
/// campaign's feed-axis sensors, say): no candidate for a regression, and
/// named in one note rather than one per channel.
QStringList unloggedChannels(const std::vector<RunData>& runs);

/// The first channel of a role the run can use (it has a rise), or nullptr: the
/// air and structure channels the screw model's readings follow.
const TemperatureRise* firstUsableOfRole(const RunData& run, ChannelRole role);

/// The channel of a role for a model that needs it: of several, the one nearest
/// the screw's fixed end by declared position, else the first declared.
const TemperatureRise& channelForRole(const RunData& run, ChannelRole role, const QString& model);

/// Axis position relative to the screw's fixed end, x − x_fixed, of each point.
Eigen::VectorXd positionsFromFixedEnd(const RunData& run, const std::vector<PredictionPoint>& at);

/// The rows of `perRun` for each run, stacked in run order (training sets).
Eigen::MatrixXd stackRows(const std::vector<RunData>& runs,
                          const std::function<Eigen::MatrixXd(const RunData&)>& perRun);

}  // namespace driftlab::models
