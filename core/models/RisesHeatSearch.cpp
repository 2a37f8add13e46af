#include "core/models/RisesHeatSearch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/models/CrossValidation.h"
#include "core/models/HeatSourceInputs.h"
#include "core/models/LaggedSensorsSearch.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {
namespace {

constexpr double kRadPerSPerKrpm = 2 * std::numbers::pi * 1000 / 60;

}  // namespace

QString SpindleHeat::describe() const {
    return QStringLiteral("the spindle's %1 through a lag of %2")
        .arg(key(), arx::minutesOrHours(tau_s));
}

QString SpindleHeat::key() const {
    return exponent == 1 ? QStringLiteral("speed") : QStringLiteral("speed²");
}

QString SpindleHeat::unit() const {
    return exponent == 1 ? QStringLiteral("krpm") : QStringLiteral("krpm²");
}

RunData thinnedRun(const RunData& run, int rows) {
    RunData part = run;
    const std::size_t step = std::max<std::size_t>(1, run.observations.size() / std::size_t(rows));
    part.observations.clear();
    for (std::size_t i = 0; i < run.observations.size(); i += step)
        part.observations.push_back(run.observations[i]);
    return part;
}

PiecewiseInput spindleHeatInput(const RunData& run, int exponent, const QString& model) {
    PiecewiseInput input = spindleSpeed(run, model);
    for (double& v : input.value) v = std::pow(v / kRadPerSPerKrpm, exponent);
    return input;
}

Eigen::MatrixXd spindleHeatAt(const RunData& run, const SpindleHeat& heat,
                              const std::vector<PredictionPoint>& at, const QString& model) {
    if (heat.none()) return Eigen::MatrixXd(Eigen::Index(at.size()), 0);
    return lagResponse(spindleHeatInput(run, heat.exponent, model), heat.tau_s, arx::timesOf(at));
}

Eigen::MatrixXd withHeatAndOffset(const Eigen::MatrixXd& features, const Eigen::MatrixXd& heat) {
    Eigen::MatrixXd X(features.rows(), features.cols() + heat.cols() + 1);
    X << features, heat, Eigen::VectorXd::Ones(features.rows());
    return X;
}

RisesHeatSearch::RisesHeatSearch(const std::vector<RunData>& training, const QString& model,
                                 const RisesHeatOptions& options, FitSummary& summary) {
    if (training.empty() || training.front().positionDependent())
        throw ModelError(QStringLiteral("model '%1' predicts a spindle's drift channel (its heat "
                                        "is the spindle speed), not a positioning error")
                             .arg(model));
    if (!(options.min_tau_s > 0) || !(options.max_tau_s > options.min_tau_s) ||
        !(options.tau_step > 1))
        throw ModelError(
            QStringLiteral("model '%1' needs a time-constant grid with 0 < min < max and a "
                           "step above 1")
                .arg(model));
    m_channels = arx::usableChannels(training, model, false, summary);
    std::vector<RunData> search;
    for (const RunData& run : training)
        search.push_back(thinnedRun(run, options.search_rows_per_run));
    m_folds = crossValidationFolds(search, options.time_blocks);
    m_observed = stackRows(search, &RunData::observedErrors);
    m_rises = stackRows(search, [&](const RunData& run) {
        return risesAt(run, m_channels, run.observationPoints());
    });
    m_heats.push_back({});
    m_columns.emplace_back(m_rises.rows(), 0);

    // The heat needs two training runs: the time blocks of one share its
    // speed programme and cannot test a heat law on motion the fit has not
    // seen (as for `arx-all`).
    if (training.size() < 2) {
        m_heatNote = QStringLiteral(
            "no lagged heat input: one training run, whose time blocks share one speed "
            "programme");
        return;
    }
    std::vector<std::vector<PiecewiseInput>> inputs;  // per exponent, per run
    try {
        for (int exponent : {1, 2}) {
            inputs.emplace_back();
            for (const RunData& run : search)
                inputs.back().push_back(spindleHeatInput(run, exponent, model));
        }
    } catch (const ModelError& e) {
        m_heatNote = QStringLiteral("no lagged heat input: %1").arg(e.message);
        return;
    }
    double shortest_s = std::numeric_limits<double>::infinity();
    for (const RunData& run : training) {
        const std::vector<PredictionPoint> at = run.observationPoints();
        shortest_s = std::min(shortest_s, arx::lastTime(at) - at.front().time_s);
    }
    std::vector<std::vector<double>> times;
    for (const RunData& run : search) times.push_back(arx::timesOf(run.observationPoints()));
    const double longest_s = std::min(options.max_tau_s, shortest_s * options.max_heat_tau_of_run);
    for (std::size_t e = 0; e < inputs.size(); ++e)
        for (double tau = options.min_tau_s; tau <= longest_s * 1.0001; tau *= options.tau_step) {
            Eigen::MatrixXd column(m_rises.rows(), 1);
            Eigen::Index at = 0;
            for (std::size_t r = 0; r < search.size(); ++r) {
                const Eigen::VectorXd part = lagResponse(inputs[e][r], tau, times[r]);
                column.col(0).segment(at, part.size()) = part;
                at += part.size();
            }
            m_heats.push_back({int(e) + 1, tau});
            m_columns.push_back(std::move(column));
        }
}

void reportHeatAndOffset(FitSummary& summary, const Eigen::VectorXd& coefficients,
                         const Eigen::VectorXd& sigma, const SpindleHeat& heat,
                         Eigen::Index heatColumn) {
    const Eigen::Index last = coefficients.size() - 1;
    summary.parameters[QStringLiteral("c")] = {coefficients[last], sigma[last],
                                               QStringLiteral("µm")};
    if (heat.none()) return;
    summary.parameters[heat.key() + QStringLiteral(".a_lag")] = {
        coefficients[heatColumn], sigma[heatColumn], QStringLiteral("µm/%1").arg(heat.unit())};
    // The grid step sets how well τ is known; no 1σ is claimed for it.
    summary.parameters[heat.key() + QStringLiteral(".tau")] = {
        heat.tau_s, std::numeric_limits<double>::quiet_NaN(), QStringLiteral("s")};
}

}  // namespace driftlab::models
