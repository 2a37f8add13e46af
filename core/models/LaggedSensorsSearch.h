#pragma once
// The search of the lagged-sensors model (`arx`) over sensors and time
// constants, and the inputs and designs it shares with the model: a sensor's
// rise through a first-order lag started at rest at the run's start, and a
// drift channel's zero per training run.

#include <Eigen/Core>
#include <QStringList>
#include <limits>
#include <utility>
#include <vector>

#include "core/models/FirstOrderLag.h"
#include "core/models/LaggedSensorsModel.h"
#include "core/models/LeastSquares.h"
#include "core/models/ThermalErrorData.h"

namespace driftlab::models::arx {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// A sensor set's cross-validated RMS, and whether a drift channel's held-out
/// runs were better predicted with the mean of the training runs' zeros.
struct SetScore {
    double rms_um = kInfinity;
    bool commonZero = false;
};

/// The rise from the run's start as a lag input: each sample interval holds
/// the mean of its two ends, so the filtered rise is not delayed by half a
/// sample.
PiecewiseInput riseInput(const RunData& run, const QString& channel);

/// Whether the channel's rise, over some training run, spans more than ten
/// times its noise (from successive differences, which a slow rise hardly
/// touches). A flat channel (the room thermometer of a steady room) carries no
/// heat; lagged, its noise becomes a slow wander that a fit can match by chance.
bool risesAboveItsNoise(const std::vector<RunData>& training, const QString& channel);

/// The training runs' temperature channels a lag model can use: logged in
/// every run, with a rise and a lag input at every observation, and with
/// `aboveNoise` rising above its noise (risesAboveItsNoise); a note in
/// `summary` for each left out. Throws ModelError naming `model` when none is
/// left.
QStringList usableChannels(const std::vector<RunData>& training, const QString& model,
                           bool aboveNoise, FitSummary& summary);

/// A time constant as a note gives it: "25 min", or "2.0 h" from 1.5 h on.
QString minutesOrHours(double tau_s);

/// The latest of the points' times (0 for none).
double lastTime(const std::vector<PredictionPoint>& at);

/// The points' times, in their order (the times a lag response is read at).
std::vector<double> timesOf(const std::vector<PredictionPoint>& at);

/// Columns [ΔT, L_τ[ΔT]] per input, position-gain copies beside them for a
/// positioning error.
Eigen::MatrixXd designOf(const Eigen::MatrixXd& features, const Eigen::VectorXd& dx,
                         bool positionDependent);

/// A drift channel's design for fitting: one zero per training run beside the
/// gains (`runOfRow`: each row's run, 0…runs−1). Each run's drift is measured
/// from the median of its first minute, and that median carries the minute's
/// noise (0.04 µm of a 0.1 µm probe's); one offset common to all runs would
/// leave those zeros to the gains, which then bend to follow a few runs'
/// noise. A prediction takes no zero, its inputs being zero where the drift's
/// zero was taken (the rises from the same first minute, the lags from rest),
/// or the runs' mean zero where cross-validation finds an offset the runs
/// share (a model that follows the drift's form only nearly).
Eigen::MatrixXd withRunZeros(const Eigen::MatrixXd& X, const std::vector<int>& runOfRow, int runs);

/// withRunZeros for the rows `rows` of a design (X holds those rows), their
/// runs numbered in order of appearance.
Eigen::MatrixXd withZerosOfTheirRuns(const Eigen::MatrixXd& X, const std::vector<int>& runOfRow,
                                     const std::vector<Eigen::Index>& rows);

/// A drift channel's `zero.<run>` parameters, whose columns start at `first`,
/// `c` (their mean) where the prediction takes it, and a note saying which.
void reportRunZeros(FitSummary& summary, const LeastSquaresFit& fit, Eigen::Index first,
                    const std::vector<RunData>& training, bool commonZero);

/// A drift channel's cross-validated RMS over `folds` (see
/// crossValidationFolds) of the design F fitted with each training run's zero
/// apart (`runOfRow`: each row's run), predicting the held-out rows with no
/// zero or with the mean of the training runs' zeros, whichever is better.
SetScore crossValidatedWithRunZeros(const Eigen::MatrixXd& F, const Eigen::VectorXd& y,
                                    const std::vector<int>& folds,
                                    const std::vector<int>& runOfRow);

/// The search over sensors and time constants, on a thinned set of rows whose
/// features are computed once for every grid time constant.
class InputSearch {
public:
    InputSearch(const std::vector<RunData>& training, const QStringList& candidates,
                const LaggedSensorsOptions& options);
    const std::vector<double>& grid() const { return m_grid; }

    /// Time-constant grid indices for the sensors `chosen` fitted on the rows
    /// not in `heldOut` (−1: none), by coordinate descent; returns the RSS too.
    std::pair<std::vector<int>, double> fitTaus(const std::vector<int>& chosen, int heldOut) const;

    /// RMS of the held-out residuals, every fold refitting its time constants;
    /// for a drift channel, of the better of predicting with no zero and with
    /// the mean of the training runs' zeros.
    SetScore crossValidated(const std::vector<int>& chosen) const;

private:
    static void append(Eigen::VectorXd& to, const Eigen::VectorXd& part);
    std::vector<Eigen::Index> rowsOutside(int fold) const;
    std::vector<Eigen::Index> rowsIn(int fold) const;
    Eigen::MatrixXd design(const std::vector<int>& chosen, const std::vector<int>& index,
                           const std::vector<Eigen::Index>& rows) const;
    /// The design a fit on `rows` solves: a drift channel's with a zero for
    /// each run among them.
    Eigen::MatrixXd fitDesign(const std::vector<int>& chosen, const std::vector<int>& index,
                              const std::vector<Eigen::Index>& rows) const;
    double rss(const std::vector<int>& chosen, const std::vector<int>& index,
               const std::vector<Eigen::Index>& rows) const;

    bool m_positionDependent;
    std::vector<double> m_grid;
    std::vector<int> m_folds;
    std::vector<int> m_runOf;  ///< each row's training run
    int m_foldCount = 0;
    Eigen::VectorXd y_, m_dx;
    std::vector<Eigen::VectorXd> m_raw;     ///< per candidate
    std::vector<Eigen::VectorXd> m_lagged;  ///< per candidate and grid τ
};

}  // namespace driftlab::models::arx
