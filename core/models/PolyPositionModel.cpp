#include "core/models/PolyPositionModel.h"

#include "core/models/CrossValidation.h"
#include "core/models/LeastSquares.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {

PolyPositionModel::PolyPositionModel(PolyPositionOptions options) : options_(options) {}

QString PolyPositionModel::describe() const {
    return QStringLiteral(
               "Polynomial (degree up to %1, chosen by cross-validation) in the nut "
               "temperature rise plus a linear bearing term, times the distance from "
               "the screw's fixed end.")
        .arg(options_.max_degree);
}

Eigen::MatrixXd PolyPositionModel::design(const RunData& run,
                                          const std::vector<PredictionPoint>& at,
                                          int degree) const {
    const Eigen::MatrixXd rises = risesAt(run, {nut_, bearing_}, at);
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
    if (options_.max_degree < 1 || options_.max_degree > 4)
        throw ModelError(QStringLiteral("model 'poly-position' takes a degree of 1 to 4, not %1")
                             .arg(options_.max_degree));
    const RunData& first = training.front();
    nut_ = channelForRole(first, ChannelRole::Nut, name()).channel_id;
    bearing_ = channelForRole(first, ChannelRole::Bearing, name()).channel_id;

    const Eigen::VectorXd y = stackRows(training, &RunData::observedErrors);
    auto stackedDesign = [&](int degree) {
        return stackRows(training, [&](const RunData& run) {
            return design(run, run.observationPoints(), degree);
        });
    };
    const std::vector<int> folds = crossValidationFolds(training, options_.time_blocks);
    std::vector<double> scores;
    for (int d = 1; d <= options_.max_degree; ++d)
        scores.push_back(crossValidatedRms(stackedDesign(d), y, folds));
    const std::size_t chosen = simplestNearBest(scores);
    if (chosen == scores.size())
        throw ModelError(QStringLiteral("model 'poly-position': %1 observations in %2 training "
                                        "run(s) are too few to cross-validate its degree")
                             .arg(y.size())
                             .arg(training.size()));
    degree_ = int(chosen) + 1;
    const LeastSquaresFit fit = solveLeastSquares(stackedDesign(degree_), y);
    coefficients_ = fit.coefficients;

    FitSummary summary;
    const bool perMm = first.positionDependent();
    const QString unitBase = perMm ? QStringLiteral("µm/(mm·K%1)") : QStringLiteral("µm/K%1");
    const char* const powers[] = {"", "²", "³", "⁴"};
    for (int i = 1; i <= degree_; ++i)
        summary.parameters[QStringLiteral("a%1").arg(i)] = {
            coefficients_[i - 1], fit.sigma[i - 1], unitBase.arg(QString::fromUtf8(powers[i - 1]))};
    summary.parameters[QStringLiteral("b")] = {coefficients_[degree_], fit.sigma[degree_],
                                               unitBase.arg(QString())};
    summary.parameters[QStringLiteral("c")] = {
        coefficients_[degree_ + 1], fit.sigma[degree_ + 1],
        perMm ? QStringLiteral("µm/mm") : QStringLiteral("µm")};
    summary.metrics[QStringLiteral("degree")] = degree_;
    summary.metrics[QStringLiteral("cv_rms_um")] = scores[chosen];
    summary.notes << QStringLiteral("degree %1 chosen by cross-validation").arg(degree_);
    summary.inputs << nut_ << bearing_;
    return summary;
}

Eigen::VectorXd PolyPositionModel::predictRun(const RunData& run,
                                              const std::vector<PredictionPoint>& at) const {
    return design(run, at, degree_) * coefficients_;
}

}  // namespace driftlab::models
