#include "core/models/MlrModel.h"

#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

#include "core/models/CrossValidation.h"
#include "core/models/LeastSquares.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {
namespace {

/// Calls `visit` with each k-subset of {0, …, n−1}, in lexicographic order.
void forEachSubset(int n, int k, const std::function<void(const std::vector<int>&)>& visit) {
    std::vector<int> subset(std::size_t(k), 0);
    std::iota(subset.begin(), subset.end(), 0);
    for (;;) {
        visit(subset);
        int i = k - 1;
        while (i >= 0 && subset[std::size_t(i)] == n - k + i) --i;
        if (i < 0) return;
        ++subset[std::size_t(i)];
        for (int j = i + 1; j < k; ++j) subset[std::size_t(j)] = subset[std::size_t(j - 1)] + 1;
    }
}

}  // namespace

MlrModel::MlrModel(MlrOptions options) : m_options(options) {}

QString MlrModel::describe() const {
    return QStringLiteral(
               "Multiple linear regression of the thermal error on the temperature rises "
               "of up to %1 sensors chosen by cross-validation, each with a gain that "
               "grows linearly from the screw's fixed end.")
        .arg(m_options.max_sensors);
}

Eigen::MatrixXd MlrModel::inputsAt(const RunData& run, const QStringList& channels,
                                   const std::vector<PredictionPoint>& at) const {
    Eigen::MatrixXd rises = risesAt(run, channels, at);
    if (!m_ambient.isEmpty()) rises.colwise() -= risesAt(run, {m_ambient}, at).col(0);
    return rises;
}

Eigen::MatrixXd MlrModel::design(const Eigen::MatrixXd& inputs, const Eigen::VectorXd& dx,
                                 bool positionDependent) {
    if (positionDependent) return withPositionGain(inputs, dx);
    Eigen::MatrixXd X(inputs.rows(), inputs.cols() + 1);
    X << inputs, Eigen::VectorXd::Ones(inputs.rows());
    return X;
}

FitSummary MlrModel::fitRuns(const std::vector<RunData>& training) {
    if (m_options.max_sensors < 1)
        throw ModelError(QStringLiteral("model 'mlr' needs at least one sensor (max_sensors)"));
    FitSummary summary;
    const bool positionDependent = training.front().positionDependent();
    m_ambient.clear();
    if (m_options.ambient_reference) {
        m_ambient = channelForRole(training.front(), ChannelRole::Ambient, name()).channel_id;
        for (const RunData& run : training) risesAt(run, {m_ambient}, run.observationPoints());
    }

    // Candidates: every temperature channel but ambient that every training run can give.
    const Eigen::VectorXd y = stackRows(training, &RunData::observedErrors);
    const Eigen::VectorXd dx = stackRows(training, [](const RunData& run) {
        return positionsFromFixedEnd(run, run.observationPoints());
    });
    QStringList candidates;
    std::vector<Eigen::VectorXd> columns;
    const QStringList unlogged = unloggedChannels(training);
    if (!unlogged.isEmpty())
        summary.notes << QStringLiteral("not logged in the training runs: %1")
                             .arg(unlogged.join(QStringLiteral(", ")));
    for (const TemperatureRise& channel : training.front().temperatures) {
        if (channel.role == ChannelRole::Ambient || unlogged.contains(channel.channel_id)) continue;
        try {
            columns.push_back(stackRows(training, [&](const RunData& run) {
                return inputsAt(run, {channel.channel_id}, run.observationPoints());
            }));
            candidates << channel.channel_id;
        } catch (const ModelError& e) {
            summary.notes << QStringLiteral("left out: %1").arg(e.message);
        }
    }
    if (candidates.isEmpty())
        throw ModelError(QStringLiteral("model 'mlr' has no usable temperature channel besides "
                                        "ambient (%1)")
                             .arg(summary.notes.join(QStringLiteral("; "))));
    Eigen::MatrixXd C(y.size(), Eigen::Index(columns.size()));
    for (std::size_t j = 0; j < columns.size(); ++j) C.col(Eigen::Index(j)) = columns[j];

    // Best subset of each size by cross-validation, then the simplest size
    // that is nearly as good as the best.
    const std::vector<int> folds = crossValidationFolds(training, m_options.time_blocks);
    m_best_subsets.clear();
    std::vector<std::vector<int>> bestColumns;
    std::vector<double> scores;
    const int largest = std::min(m_options.max_sensors, int(candidates.size()));
    const Eigen::MatrixXd everySensor = design(C, dx, positionDependent);
    const FoldNormalEquations normalEquations(everySensor, y, folds);
    const auto candidateCount = Eigen::Index(candidates.size());
    std::vector<Eigen::Index> designColumns;  // of a subset, within everySensor
    for (int k = 1; k <= largest; ++k) {
        double bestScore = std::numeric_limits<double>::infinity();
        std::vector<int> best;
        forEachSubset(int(candidates.size()), k, [&](const std::vector<int>& subset) {
            designColumns.assign(subset.begin(), subset.end());
            if (positionDependent)
                for (int j : subset) designColumns.push_back(candidateCount + j);  // position gains
            else
                designColumns.push_back(candidateCount);  // the offset
            const double cv = normalEquations.crossValidatedRms(designColumns);
            if (cv < bestScore) {
                bestScore = cv;
                best = subset;
            }
        });
        if (best.empty()) break;
        SubsetScore score{{}, bestScore};
        for (int j : best) score.sensors << candidates[j];
        m_best_subsets.push_back(score);
        bestColumns.push_back(best);
        scores.push_back(bestScore);
    }
    const std::size_t chosen = simplestNearBest(scores);
    if (chosen == scores.size())
        throw ModelError(QStringLiteral("model 'mlr': %1 observations in %2 training run(s) are "
                                        "too few to cross-validate any sensor subset")
                             .arg(y.size())
                             .arg(training.size()));

    m_sensors = m_best_subsets[chosen].sensors;
    const LeastSquaresFit fit =
        solveLeastSquares(design(C(Eigen::all, bestColumns[chosen]), dx, positionDependent), y);
    m_coefficients = fit.coefficients;
    const Eigen::Index m = m_sensors.size();
    for (Eigen::Index j = 0; j < m; ++j) {
        const QString& s = m_sensors[j];
        summary.parameters[s + QStringLiteral(".a")] = {m_coefficients[j], fit.sigma[j],
                                                        QStringLiteral("µm/K")};
        if (positionDependent)
            summary.parameters[s + QStringLiteral(".b")] = {m_coefficients[m + j], fit.sigma[m + j],
                                                            QStringLiteral("µm/(K·mm)")};
    }
    if (!positionDependent)
        summary.parameters[QStringLiteral("c")] = {m_coefficients[m], fit.sigma[m],
                                                   QStringLiteral("µm")};
    summary.metrics[QStringLiteral("cv_rms_um")] = scores[chosen];
    summary.metrics[QStringLiteral("r2")] = rSquared(fit.rss, y);

    const LeastSquaresFit single =
        solveLeastSquares(design(C(Eigen::all, bestColumns.front()), dx, positionDependent), y);
    const double singleR2 = rSquared(single.rss, y);
    summary.metrics[QStringLiteral("best_single_cv_rms_um")] = scores.front();
    summary.metrics[QStringLiteral("best_single_r2")] = singleR2;
    summary.notes << QStringLiteral("sensors chosen by cross-validation: %1")
                         .arg(m_sensors.join(QStringLiteral(", ")))
                  << QStringLiteral("best single sensor: %1 (R² = %2, cross-validated RMS %3 µm)")
                         .arg(m_best_subsets.front().sensors.front())
                         .arg(singleR2, 0, 'f', 4)
                         .arg(scores.front(), 0, 'g', 3);
    summary.inputs = m_sensors;
    if (!m_ambient.isEmpty()) summary.inputs << m_ambient;
    return summary;
}

Eigen::VectorXd MlrModel::predictRun(const RunData& run,
                                     const std::vector<PredictionPoint>& at) const {
    return design(inputsAt(run, m_sensors, at), positionsFromFixedEnd(run, at),
                  run.positionDependent()) *
           m_coefficients;
}

}  // namespace driftlab::models
