#include "core/models/PrincipalRisesHeatModel.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/models/CrossValidation.h"
#include "core/models/LeastSquares.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {

PrincipalRisesHeatModel::PrincipalRisesHeatModel(RisesHeatOptions options) : m_options(options) {}

QString PrincipalRisesHeatModel::describe() const {
    return QStringLiteral(
        "The first principal components of the standardised temperature rises, the spindle's "
        "heat through a first-order lag and one offset; the number of components and the heat "
        "chosen together by cross-validation over the training runs.");
}

Eigen::MatrixXd PrincipalRisesHeatModel::design(const RunData& run,
                                                const std::vector<PredictionPoint>& at) const {
    return withHeatAndOffset(risesAt(run, m_channels, at), spindleHeatAt(run, m_heat, at, name()));
}

FitSummary PrincipalRisesHeatModel::fitRuns(const std::vector<RunData>& training) {
    FitSummary summary;
    m_heat = {};
    m_components = 0;
    const RisesHeatSearch search(training, name(), m_options, summary);
    m_channels = search.channels();
    const auto rises = Eigen::Index(m_channels.size());

    // Standardised over every training row, the loadings from its SVD.
    const Eigen::MatrixXd all = stackRows(training, [&](const RunData& run) {
        return risesAt(run, m_channels, run.observationPoints());
    });
    const Eigen::RowVectorXd mean = all.colwise().mean();
    // A channel that stays still gives a zero column whatever its scale.
    const Eigen::RowVectorXd spread =
        ((all.rowwise() - mean).array().square().colwise().mean()).sqrt().matrix();
    const Eigen::RowVectorXd scale = (spread.array() > 0).select(spread, 1.0);
    const Eigen::MatrixXd z = (all.rowwise() - mean).array().rowwise() / scale.array();
    const Eigen::BDCSVD<Eigen::MatrixXd> svd(z, Eigen::ComputeThinV);
    const Eigen::MatrixXd loadings = svd.matrixV();
    const Eigen::Index most = std::min<Eigen::Index>(kMaxComponents, loadings.cols());
    const Eigen::MatrixXd scores =
        (((search.rises().rowwise() - mean).array().rowwise() / scale.array()).matrix() * loadings)
            .leftCols(most);

    // Every candidate's design [components, heat, 1], its folds' normal
    // equations formed once; k components are its first k columns.
    std::vector<Eigen::MatrixXd> designs;
    designs.reserve(search.heats().size());
    for (std::size_t c = 0; c < search.heats().size(); ++c)
        designs.push_back(withHeatAndOffset(scores, search.heatColumn(c)));
    std::vector<FoldNormalEquations> systems;
    for (const Eigen::MatrixXd& X : designs)
        systems.emplace_back(X, search.observed(), search.folds());
    double best = std::numeric_limits<double>::infinity();
    for (Eigen::Index k = 1; k <= most; ++k) {
        if (cancelRequested())
            throw ModelError(QStringLiteral("model '%1': fit cancelled").arg(name()));
        for (std::size_t c = 0; c < designs.size(); ++c) {
            std::vector<Eigen::Index> columns(static_cast<std::size_t>(k));
            std::iota(columns.begin(), columns.end(), 0);
            for (Eigen::Index extra = most; extra < designs[c].cols(); ++extra)
                columns.push_back(extra);
            const double cv = systems[c].crossValidatedRms(columns);
            if (cv < best) {
                best = cv;
                m_components = int(k);
                m_heat = search.heats()[c];
            }
        }
    }
    if (!std::isfinite(best))
        throw ModelError(QStringLiteral("model '%1': the training runs are too few to "
                                        "cross-validate the rises' components (%2 channels)")
                             .arg(name())
                             .arg(rises));

    // The final fit on every observation, its gains carried back to the
    // rises: a = diag(1/σ)·V_k·β, and the offset less Σ a_j·μ_j.
    const Eigen::MatrixXd V = loadings.leftCols(m_components);
    Eigen::MatrixXd X = stackRows(training, [&](const RunData& run) {
        const std::vector<PredictionPoint> at = run.observationPoints();
        const Eigen::MatrixXd zr =
            (risesAt(run, m_channels, at).rowwise() - mean).array().rowwise() / scale.array();
        return withHeatAndOffset(zr * V, spindleHeatAt(run, m_heat, at, name()));
    });
    const Eigen::VectorXd observed = stackRows(training, &RunData::observedErrors);
    const LeastSquaresFit fit = solveLeastSquares(X, observed);
    const Eigen::Index k = m_components;
    const Eigen::Index tail = fit.coefficients.size() - k;  // the heat's and the offset
    m_coefficients.resize(rises + tail);
    m_coefficients.head(rises) = (V * fit.coefficients.head(k)).array() / scale.transpose().array();
    m_coefficients.tail(tail) = fit.coefficients.tail(tail);
    m_coefficients[m_coefficients.size() - 1] -= mean.dot(m_coefficients.head(rises));

    // The rises' gains and the offset come from the components' gains: no
    // 1σ is claimed for them here, the components' own are given.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Eigen::VectorXd sigma = Eigen::VectorXd::Constant(m_coefficients.size(), nan);
    sigma.segment(rises, tail - 1) = fit.sigma.segment(k, tail - 1);
    for (Eigen::Index i = 0; i < k; ++i)
        summary.parameters[QStringLiteral("pc%1.b").arg(i + 1)] = {
            fit.coefficients[i], fit.sigma[i], QStringLiteral("µm")};
    for (Eigen::Index j = 0; j < rises; ++j)
        summary.parameters[m_channels[j] + QStringLiteral(".a")] = {m_coefficients[j], nan,
                                                                    QStringLiteral("µm/K")};
    reportHeatAndOffset(summary, m_coefficients, sigma, m_heat, rises);
    summary.metrics[QStringLiteral("cv_rms_um")] = best;
    summary.metrics[QStringLiteral("components")] = double(m_components);
    summary.metrics[QStringLiteral("r2")] = rSquared(fit.rss, observed);
    if (!search.heatNote().isEmpty()) summary.notes << search.heatNote();
    summary.notes << QStringLiteral(
                         "the first %1 principal component(s) of the %2 standardised rises, "
                         "one offset%3, by cross-validation (RMS %4 µm)")
                         .arg(m_components)
                         .arg(rises)
                         .arg(m_heat.none() ? QStringLiteral(" and no lagged heat")
                                            : QStringLiteral(" and ") + m_heat.describe())
                         .arg(best, 0, 'g', 3);
    summary.inputs = m_channels;
    return summary;
}

Eigen::VectorXd PrincipalRisesHeatModel::predictRun(const RunData& run,
                                                    const std::vector<PredictionPoint>& at) const {
    return design(run, at) * m_coefficients;
}

}  // namespace driftlab::models
