#include "core/models/LaggedSensorsModel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/models/CrossValidation.h"
#include "core/models/LaggedSensorsSearch.h"
#include "core/models/LeastSquares.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {
namespace {

using arx::designOf;
using arx::InputSearch;
using arx::lastTime;
using arx::riseInput;
using arx::risesAboveItsNoise;
using arx::SetScore;
using arx::timesOf;
using arx::withRunZeros;

}  // namespace

LaggedSensorsModel::LaggedSensorsModel(LaggedSensorsOptions options) : m_options(options) {}

QString LaggedSensorsModel::describe() const {
    return QStringLiteral(
               "Dynamic regression: up to %1 sensors chosen by cross-validation over the "
               "training runs, each entering with its current temperature rise and with its "
               "rise through a first-order lag of fitted time constant, so that drift which "
               "lags the sensors is followed.")
        .arg(m_options.max_sensors);
}

FitSummary LaggedSensorsModel::fitRuns(const std::vector<RunData>& training) {
    if (m_options.max_sensors < 1 || m_options.grid_points < 2 || !(m_options.min_tau_s > 0) ||
        !(m_options.max_tau_s > m_options.min_tau_s))
        throw ModelError(
            QStringLiteral("model 'arx' needs at least one sensor and a time-constant "
                           "grid of 2 or more points with 0 < min < max"));
    FitSummary summary;
    const QStringList candidates =
        arx::usableChannels(training, QStringLiteral("arx"), true, summary);

    // Forward selection: the sensor that most lowers the cross-validated RMS,
    // one at a time; then the simplest set nearly as good as the best.
    const InputSearch search(training, candidates, m_options);
    struct SensorSet {
        std::vector<int> sensors;
        SetScore score;
        std::vector<int> tau_index;  ///< fitted on every training run
    };
    std::vector<SensorSet> sets;
    std::vector<int> chosen;
    const int largest = std::min(m_options.max_sensors, int(candidates.size()));
    for (int size = 1; size <= largest; ++size) {
        if (cancelRequested()) throw ModelError(QStringLiteral("model 'arx': fit cancelled"));
        SetScore best;
        int bestSensor = -1;
        for (int j = 0; j < int(candidates.size()); ++j) {
            if (std::find(chosen.begin(), chosen.end(), j) != chosen.end()) continue;
            std::vector<int> trial = chosen;
            trial.push_back(j);
            const SetScore cv = search.crossValidated(trial);
            if (cv.rms_um < best.rms_um) {
                best = cv;
                bestSensor = j;
            }
        }
        if (bestSensor < 0) break;
        chosen.push_back(bestSensor);
        std::vector<int> tauIndex = search.fitTaus(chosen, -1).first;
        // A further sensor lagged by the longest time constant searched acts
        // over the runs as a trend, which the runs cannot tell from a heat
        // path (a wandering bed thermometer fitted 0.02 µm of a noise-free
        // drift's misfit so): the search stops before it.
        if (chosen.size() > 1 && tauIndex.back() + 1 == int(search.grid().size())) break;
        sets.push_back({chosen, best, std::move(tauIndex)});
    }
    // Each sensor adds three parameters, and opposed gains on correlated
    // sensors amplify their noise on motion the training runs did not show:
    // a further sensor must lower the cross-validated RMS by 10 %.
    std::vector<double> scores;
    for (const SensorSet& set : sets) scores.push_back(set.score.rms_um);
    const std::size_t pick = simplestNearBest(scores, 0.10);
    if (pick == scores.size())
        throw ModelError(
            QStringLiteral("model 'arx': the training runs are too few to "
                           "cross-validate any sensor set"));

    const std::vector<int>& set = sets[pick].sensors;
    const std::vector<int>& index = sets[pick].tau_index;
    m_inputs.clear();
    for (std::size_t k = 0; k < set.size(); ++k)
        m_inputs.push_back({candidates[set[k]], search.grid()[std::size_t(index[k])]});

    // Gains on every observation, at the chosen time constants.
    const bool positionDependent = training.front().positionDependent();
    const Eigen::MatrixXd X = stackRows(training, [&](const RunData& run) {
        const std::vector<PredictionPoint> at = run.observationPoints();
        return designOf(LaggedSensorsModel::features(run, at), positionsFromFixedEnd(run, at),
                        positionDependent);
    });
    const Eigen::VectorXd y = stackRows(training, &RunData::observedErrors);
    std::vector<int> runOfRow;
    for (std::size_t r = 0; r < training.size(); ++r)
        runOfRow.insert(runOfRow.end(), training[r].observations.size(), int(r));
    const LeastSquaresFit fit = solveLeastSquares(
        positionDependent ? X : withRunZeros(X, runOfRow, int(training.size())), y);
    m_coefficients = fit.coefficients.head(X.cols());
    m_commonZero_um = 0;
    if (!positionDependent && sets[pick].score.commonZero)
        m_commonZero_um = fit.coefficients.tail(Eigen::Index(training.size())).mean();

    const Eigen::Index m = 2 * Eigen::Index(m_inputs.size());
    QStringList described;
    for (std::size_t k = 0; k < m_inputs.size(); ++k) {
        const QString& s = m_inputs[k].channel;
        const Eigen::Index a = 2 * Eigen::Index(k), g = a + 1;
        // The grid step sets how well τ is known; no 1σ is claimed for it.
        summary.parameters[s + QStringLiteral(".tau")] = {
            m_inputs[k].tau_s, std::numeric_limits<double>::quiet_NaN(), QStringLiteral("s")};
        summary.parameters[s + QStringLiteral(".a")] = {m_coefficients[a], fit.sigma[a],
                                                        QStringLiteral("µm/K")};
        summary.parameters[s + QStringLiteral(".a_lag")] = {m_coefficients[g], fit.sigma[g],
                                                            QStringLiteral("µm/K")};
        if (positionDependent) {
            summary.parameters[s + QStringLiteral(".b")] = {m_coefficients[m + a], fit.sigma[m + a],
                                                            QStringLiteral("µm/(K·mm)")};
            summary.parameters[s + QStringLiteral(".b_lag")] = {
                m_coefficients[m + g], fit.sigma[m + g], QStringLiteral("µm/(K·mm)")};
        }
        described << QStringLiteral("%1 (lag %2)").arg(s, arx::minutesOrHours(m_inputs[k].tau_s));
        if (index[k] == 0 || index[k] + 1 == int(search.grid().size()))
            summary.notes << QStringLiteral(
                                 "the lag of %1 sits at the search bound (%2): the "
                                 "training runs do not pin it down")
                                 .arg(s, arx::minutesOrHours(m_inputs[k].tau_s));
        summary.inputs << s;
    }
    if (!positionDependent)
        arx::reportRunZeros(summary, fit, m, training, sets[pick].score.commonZero);
    summary.metrics[QStringLiteral("cv_rms_um")] = scores[pick];
    summary.metrics[QStringLiteral("best_single_cv_rms_um")] = scores.front();
    summary.metrics[QStringLiteral("r2")] = rSquared(fit.rss, y);
    summary.notes << QStringLiteral(
                         "inputs chosen by cross-validation: %1 (cross-validated RMS "
                         "%2 µm)")
                         .arg(described.join(QStringLiteral(", ")))
                         .arg(scores[pick], 0, 'g', 3);
    return summary;
}

Eigen::MatrixXd LaggedSensorsModel::features(const RunData& run,
                                             const std::vector<PredictionPoint>& at) const {
    const std::vector<double> times = timesOf(at);
    Eigen::MatrixXd F(Eigen::Index(at.size()), 2 * Eigen::Index(m_inputs.size()));
    for (std::size_t k = 0; k < m_inputs.size(); ++k) {
        F.col(2 * Eigen::Index(k)) = risesAt(run, {m_inputs[k].channel}, at).col(0);
        F.col(2 * Eigen::Index(k) + 1) =
            lagResponse(riseInput(run, m_inputs[k].channel), m_inputs[k].tau_s, times);
    }
    return F;
}

Eigen::VectorXd LaggedSensorsModel::predictRun(const RunData& run,
                                               const std::vector<PredictionPoint>& at) const {
    const Eigen::VectorXd fromInputs =
        designOf(features(run, at), positionsFromFixedEnd(run, at), run.positionDependent()) *
        m_coefficients;
    return fromInputs.array() + m_commonZero_um;
}

}  // namespace driftlab::models
