#include "core/models/RidgeHeatModel.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/models/LeastSquares.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {
namespace {

/// Each fold's fitted rows' normal equations and its held-out rows, for the
/// design `X` of the search rows.
struct FoldSystems {
    std::vector<Eigen::MatrixXd> gram, heldOutX;
    std::vector<Eigen::VectorXd> moment, heldOutY;
    std::vector<double> fittedRows;
};

FoldSystems foldSystems(const Eigen::MatrixXd& X, const Eigen::VectorXd& y,
                        const std::vector<int>& folds) {
    FoldSystems s;
    const int count = folds.empty() ? 0 : *std::max_element(folds.begin(), folds.end()) + 1;
    for (int f = 0; f < count; ++f) {
        std::vector<Eigen::Index> fitted, heldOut;
        for (std::size_t i = 0; i < folds.size(); ++i)
            (folds[i] == f ? heldOut : fitted).push_back(Eigen::Index(i));
        if (heldOut.empty()) continue;
        const Eigen::MatrixXd Xf = X(fitted, Eigen::all);
        s.gram.push_back(Xf.transpose() * Xf);
        s.moment.push_back(Xf.transpose() * y(fitted));
        s.fittedRows.push_back(double(fitted.size()));
        s.heldOutX.push_back(X(heldOut, Eigen::all));
        s.heldOutY.push_back(y(heldOut));
    }
    return s;
}

/// The held-out RMS over the folds at penalty λ; +∞ where a fold's system is
/// singular.
double crossValidatedRidgeRms(const FoldSystems& s, double lambda, Eigen::Index penalised) {
    double squares = 0, rows = 0;
    for (std::size_t f = 0; f < s.gram.size(); ++f) {
        const Eigen::VectorXd b =
            ridgeSolve(s.gram[f], s.moment[f], s.fittedRows[f], lambda, penalised);
        if (b.size() == 0) return std::numeric_limits<double>::infinity();
        squares += (s.heldOutY[f] - s.heldOutX[f] * b).squaredNorm();
        rows += double(s.heldOutY[f].size());
    }
    return std::sqrt(squares / rows);
}

}  // namespace

Eigen::VectorXd ridgeSolve(const Eigen::MatrixXd& gram, const Eigen::VectorXd& moment, double rows,
                           double lambda, Eigen::Index penalised) {
    // Scaled columns z_j = x_j / s_j with s_j their RMS: the system in z is
    // (D⁻¹·XᵀX·D⁻¹ + λ·rows·P)·β = D⁻¹·Xᵀy, and b = D⁻¹·β.
    const Eigen::VectorXd scale = ((gram.diagonal() / rows).array().sqrt() + 1e-12).matrix();
    Eigen::MatrixXd A = gram.array() / (scale * scale.transpose()).array();
    A.diagonal().head(penalised).array() += lambda * rows;
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    if (qr.rank() < A.cols()) return {};
    return (qr.solve((moment.array() / scale.array()).matrix()).array() / scale.array()).matrix();
}

RidgeHeatModel::RidgeHeatModel(RisesHeatOptions options) : m_options(options) {}

QString RidgeHeatModel::describe() const {
    return QStringLiteral(
        "Every temperature rise with a penalty on their gains (ridge regression), the "
        "spindle's heat through a first-order lag and one offset; the penalty and the heat "
        "chosen together by cross-validation over the training runs.");
}

std::vector<double> RidgeHeatModel::penalties() {
    std::vector<double> lambdas{0};
    for (int i = 0; i <= 10; ++i) lambdas.push_back(std::pow(10.0, -4 + 0.5 * i));
    return lambdas;
}

Eigen::MatrixXd RidgeHeatModel::design(const RunData& run,
                                       const std::vector<PredictionPoint>& at) const {
    return withHeatAndOffset(risesAt(run, m_channels, at), spindleHeatAt(run, m_heat, at, name()));
}

FitSummary RidgeHeatModel::fitRuns(const std::vector<RunData>& training) {
    FitSummary summary;
    m_heat = {};
    m_lambda = 0;
    const RisesHeatSearch search(training, name(), m_options, summary);
    m_channels = search.channels();
    const auto rises = Eigen::Index(m_channels.size());
    const std::vector<double> lambdas = penalties();
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < search.heats().size(); ++c) {
        if (cancelRequested())
            throw ModelError(QStringLiteral("model '%1': fit cancelled").arg(name()));
        const FoldSystems systems =
            foldSystems(withHeatAndOffset(search.rises(), search.heatColumn(c)), search.observed(),
                        search.folds());
        for (double lambda : lambdas) {
            const double cv = crossValidatedRidgeRms(systems, lambda, rises);
            if (cv < best) {
                best = cv;
                m_heat = search.heats()[c];
                m_lambda = lambda;
            }
        }
    }
    if (!std::isfinite(best))
        throw ModelError(QStringLiteral("model '%1': the training runs are too few to "
                                        "cross-validate every rise (%2 channels)")
                             .arg(name())
                             .arg(m_channels.size()));

    const Eigen::MatrixXd X = stackRows(
        training, [&](const RunData& run) { return design(run, run.observationPoints()); });
    const Eigen::VectorXd observed = stackRows(training, &RunData::observedErrors);
    // λ = 0 is least squares, solved by QR; a penalised fit's gains are
    // biased towards zero, and no 1σ is claimed for them, nor for the gains
    // fitted beside them.
    Eigen::VectorXd sigma =
        Eigen::VectorXd::Constant(X.cols(), std::numeric_limits<double>::quiet_NaN());
    if (m_lambda > 0) {
        m_coefficients = ridgeSolve(X.transpose() * X, X.transpose() * observed, double(X.rows()),
                                    m_lambda, rises);
    } else {
        const LeastSquaresFit fit = solveLeastSquares(X, observed);
        m_coefficients = fit.coefficients;
        sigma = fit.sigma;
    }
    if (m_coefficients.size() == 0)
        throw ModelError(QStringLiteral("model '%1': the heat and the offset cannot be told "
                                        "apart on the training runs")
                             .arg(name()));
    for (Eigen::Index k = 0; k < rises; ++k)
        summary.parameters[m_channels[k] + QStringLiteral(".a")] = {m_coefficients[k], sigma[k],
                                                                    QStringLiteral("µm/K")};
    reportHeatAndOffset(summary, m_coefficients, sigma, m_heat, rises);
    summary.metrics[QStringLiteral("cv_rms_um")] = best;
    summary.metrics[QStringLiteral("lambda")] = m_lambda;
    summary.metrics[QStringLiteral("r2")] =
        rSquared((observed - X * m_coefficients).squaredNorm(), observed);
    if (!search.heatNote().isEmpty()) summary.notes << search.heatNote();
    summary.notes << QStringLiteral(
                         "every rise (%1 channels) with a penalty λ = %2 on their gains, one "
                         "offset%3, by cross-validation (RMS %4 µm)")
                         .arg(m_channels.size())
                         .arg(m_lambda, 0, 'g', 3)
                         .arg(m_heat.none() ? QStringLiteral(" and no lagged heat")
                                            : QStringLiteral(" and ") + m_heat.describe())
                         .arg(best, 0, 'g', 3);
    summary.inputs = m_channels;
    return summary;
}

Eigen::VectorXd RidgeHeatModel::predictRun(const RunData& run,
                                           const std::vector<PredictionPoint>& at) const {
    return design(run, at) * m_coefficients;
}

}  // namespace driftlab::models
