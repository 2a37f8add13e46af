#include "core/models/PolyPositionModel.h"

#include "core/models/CrossValidation.h"
#include "core/models/LeastSquares.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {

PolyPositionModel::PolyPositionModel(PolyPositionOptions options) : m_options(options) {}

QString PolyPositionModel::describe() const {
    return QStringLiteral(
               "Polynomial (degree up to %1, chosen by cross-validation) in the nut "
               "temperature rise plus a linear bearing term, times the distance from "
               "the screw's fixed end.")
        .arg(m_options.max_degree);
}

Eigen::MatrixXd PolyPositionModel::design(const RunData& run,
                                          const std::vector<PredictionPoint>& at,
                                          int degree) const {
    const Eigen::MatrixXd rises = risesAt(run, {m_nut, m_bearing}, at);
    const Eigen::VectorXd gain = run.positionDependent()
                                     ? positionsFromFixedEnd(run, at)
                                     : Eigen::VectorXd::Ones(Eigen::Index(at.size()));
    Eigen::MatrixXd X(rises.rows(), degree + 2);
    for (int i = 1; i <= degree; ++i) X.col(i - 1) = rises.col(0).array().pow(i);
    X.col(degree) = rises.col(1);
    X.col(degree + 1).setOnes();
    return gain.asDiagonal() * X;
}

FitSummary PolyPositionModel::fitRuns(const std::vector<RunData>& training) {
    if (m_options.max_degree < 1 || m_options.max_degree > 4)
        throw ModelError(QStringLiteral("model 'poly-position' takes a degree of 1 to 4, not %1")
                             .arg(m_options.max_degree));
    const RunData& first = training.front();
    m_nut = channelForRole(first, ChannelRole::Nut, name()).channel_id;
    m_bearing = channelForRole(first, ChannelRole::Bearing, name()).channel_id;

    const Eigen::VectorXd y = stackRows(training, &RunData::observedErrors);
    auto stackedDesign = [&](int degree) {
        return stackRows(training, [&](const RunData& run) {
            return design(run, run.observationPoints(), degree);
        });
    };
    const std::vector<int> folds = crossValidationFolds(training, m_options.time_blocks);
    std::vector<double> scores;
    for (int d = 1; d <= m_options.max_degree; ++d)
        scores.push_back(crossValidatedRms(stackedDesign(d), y, folds));
    const std::size_t chosen = simplestNearBest(scores);
    if (chosen == scores.size())
        throw ModelError(QStringLiteral("model 'poly-position': %1 observations in %2 training "
                                        "run(s) are too few to cross-validate its degree")
                             .arg(y.size())
                             .arg(training.size()));
    m_degree = int(chosen) + 1;
    const LeastSquaresFit fit = solveLeastSquares(stackedDesign(m_degree), y);
    m_coefficients = fit.coefficients;

    FitSummary summary;
    const bool perMm = first.positionDependent();
    const QString unitBase = perMm ? QStringLiteral("µm/(mm·K%1)") : QStringLiteral("µm/K%1");
    const char* const powers[] = {"", "²", "³", "⁴"};
    for (int i = 1; i <= m_degree; ++i)
        summary.parameters[QStringLiteral("a%1").arg(i)] = {
            m_coefficients[i - 1], fit.sigma[i - 1],
            unitBase.arg(QString::fromUtf8(powers[i - 1]))};
    summary.parameters[QStringLiteral("b")] = {m_coefficients[m_degree], fit.sigma[m_degree],
                                               unitBase.arg(QString())};
    summary.parameters[QStringLiteral("c")] = {
        m_coefficients[m_degree + 1], fit.sigma[m_degree + 1],
        perMm ? QStringLiteral("µm/mm") : QStringLiteral("µm")};
    summary.metrics[QStringLiteral("degree")] = m_degree;
    summary.metrics[QStringLiteral("cv_rms_um")] = scores[chosen];
    summary.notes << QStringLiteral("degree %1 chosen by cross-validation").arg(m_degree);
    summary.inputs << m_nut << m_bearing;
    return summary;
}

Eigen::VectorXd PolyPositionModel::predictRun(const RunData& run,
                                              const std::vector<PredictionPoint>& at) const {
    return design(run, at, m_degree) * m_coefficients;
}

}  // namespace driftlab::models
