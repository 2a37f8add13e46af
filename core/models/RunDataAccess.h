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

/// Linear interpolation at `time_s`, held flat before the first sample and
/// up to a hole's length (kHoleIntervals of the signal's interval) after the
/// last; a time inside a hole left out (DataGaps.h) or later is an error.
double valueAt(const Signal& signal, double time_s, const QString& runId);

/// For an input that drives a simulation or a lag through the whole run (the
/// screw's room, a lagged rise, a heat source): linear interpolation across
/// every hole, bridged or left out, held flat beyond the ends. The screw keeps
/// simulating through a hole; the observations inside one left out are not
/// fitted or scored. Throws only for a signal without samples.
double bridgedValueAt(const Signal& signal, double time_s, const QString& runId);

/// Requires samples of the signal from the run's start (as a rise's
/// reference does: within two reference windows or a hole of its own rhythm),
/// for a continuous input read by bridgedValueAt or as a piecewise input.
void requireCoverage(const RunData& run, const Signal& signal);

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
