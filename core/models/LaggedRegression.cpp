#include "core/models/LaggedRegression.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/models/CeresResiduals.h"
#include "core/models/LeastSquares.h"
#include "core/models/ModelError.h"

namespace driftlab::models {
namespace {

/// Step of the central difference in log τ for the parameter uncertainty.
constexpr double kLogTauStep = 1e-4;

Eigen::VectorXd stacked(const std::vector<Eigen::VectorXd>& parts) {
    Eigen::Index rows = 0;
    for (const Eigen::VectorXd& p : parts) rows += p.size();
    Eigen::VectorXd v(rows);
    Eigen::Index at = 0;
    for (const Eigen::VectorXd& p : parts) {
        v.segment(at, p.size()) = p;
        at += p.size();
    }
    return v;
}

QString gainUnit(const QString& inputUnit, bool perMm) {
    if (perMm) return QStringLiteral("µm/(%1·mm)").arg(inputUnit);
    return inputUnit.contains(u'/') ? QStringLiteral("µm/(%1)").arg(inputUnit)
                                    : QStringLiteral("µm/") + inputUnit;
}

}  // namespace

LaggedRegression::LaggedRegression(std::vector<LagTerm> terms, LagSearchOptions options)
    : m_terms(std::move(terms)), m_options(options) {}

void LaggedRegression::validate(std::span<const LagCase> cases,
                                const std::vector<Eigen::VectorXd>& observed) const {
    if (!(m_options.min_tau_s > 0) || !(m_options.max_tau_s > m_options.min_tau_s) ||
        m_options.grid_points < 2)
        throw ModelError(
            QStringLiteral("the time-constant search needs 0 < min < max and at "
                           "least 2 grid points"));
    if (m_terms.empty() || m_terms.size() > 3)
        throw ModelError(QStringLiteral("a lag model takes 1 to 3 heat-source terms, not %1")
                             .arg(m_terms.size()));
    if (observed.size() != cases.size())
        throw ModelError(QStringLiteral("%1 training runs but %2 observation sets")
                             .arg(cases.size())
                             .arg(observed.size()));
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const Eigen::Index points = Eigen::Index(cases[i].time_s.size());
        for (const LagTerm& term : m_terms)
            if (term.input >= cases[i].inputs.size())
                throw ModelError(
                    QStringLiteral("term '%1' has no input in a training run").arg(term.name));
        if (observed[i].size() != points || (m_position_dependent && cases[i].dx.size() != points))
            throw ModelError(
                QStringLiteral("a training run has not one observation and position "
                               "per point"));
    }
}

Eigen::VectorXd LaggedRegression::termResponse(std::span<const LagCase> cases, std::size_t k,
                                               double tau_s) const {
    std::vector<Eigen::VectorXd> parts;
    for (const LagCase& c : cases)
        parts.push_back(lagResponse(c.inputs[m_terms[k].input], tau_s, c.time_s));
    return stacked(parts);
}

Eigen::MatrixXd LaggedRegression::responses(std::span<const LagCase> cases,
                                            const std::vector<double>& tau_s) const {
    std::vector<Eigen::VectorXd> columns;
    for (std::size_t k = 0; k < m_terms.size(); ++k)
        columns.push_back(termResponse(cases, k, tau_s[k]));
    Eigen::MatrixXd F(columns.front().size(), Eigen::Index(columns.size()));
    for (std::size_t k = 0; k < columns.size(); ++k) F.col(Eigen::Index(k)) = columns[k];
    return F;
}

Eigen::MatrixXd LaggedRegression::design(const Eigen::MatrixXd& F,
                                         const Eigen::VectorXd& dx) const {
    return m_position_dependent ? withPositionGain(F, dx) : F;
}

std::vector<double> LaggedRegression::gridSearch(std::span<const LagCase> cases,
                                                 const Eigen::VectorXd& dx,
                                                 const Eigen::VectorXd& y) const {
    const int G = m_options.grid_points;
    const std::size_t K = m_terms.size();
    std::vector<double> grid(std::size_t(G), 0.0);
    const double lo = std::log(m_options.min_tau_s), hi = std::log(m_options.max_tau_s);
    for (int g = 0; g < G; ++g) grid[std::size_t(g)] = std::exp(lo + (hi - lo) * g / (G - 1));

    // Responses for every grid τ, once per term: the search then only solves
    // small least squares.
    std::vector<Eigen::MatrixXd> byTerm(K, Eigen::MatrixXd(y.size(), G));
    for (std::size_t k = 0; k < K; ++k) {
        for (int g = 0; g < G; ++g) byTerm[k].col(g) = termResponse(cases, k, grid[std::size_t(g)]);
        if (byTerm[k].cwiseAbs().maxCoeff() == 0)
            throw ModelError(QStringLiteral("the input of '%1' is zero at every training "
                                            "observation: the training runs show no heat from it")
                                 .arg(m_terms[k].name));
    }

    // Terms on the same input are interchangeable: only ascending grid indices.
    auto admissible = [&](const std::vector<int>& index) {
        for (std::size_t k = 0; k < K; ++k)
            for (std::size_t j = 0; j < k; ++j)
                if (m_terms[j].input == m_terms[k].input && index[k] <= index[j]) return false;
        return true;
    };
    std::vector<int> index(K, 0), best;
    double bestRss = std::numeric_limits<double>::infinity();
    Eigen::MatrixXd F(y.size(), Eigen::Index(K));
    for (;;) {
        if (admissible(index)) {
            for (std::size_t k = 0; k < K; ++k) F.col(Eigen::Index(k)) = byTerm[k].col(index[k]);
            const double rss = solveLeastSquares(design(F, dx), y).rss;
            if (rss < bestRss) {
                bestRss = rss;
                best = index;
            }
        }
        std::size_t k = 0;
        while (k < K && ++index[k] == G) index[k++] = 0;
        if (k == K) break;
    }
    if (best.empty())
        throw ModelError(QStringLiteral("the time-constant grid has too few points for %1 "
                                        "terms on one input")
                             .arg(K));
    std::vector<double> tau(K);
    for (std::size_t k = 0; k < K; ++k) tau[k] = grid[std::size_t(best[k])];
    return tau;
}

std::vector<double> LaggedRegression::sortedPerInput(std::vector<double> tau_s) const {
    std::map<std::size_t, std::vector<std::size_t>> termsOfInput;
    for (std::size_t k = 0; k < m_terms.size(); ++k) termsOfInput[m_terms[k].input].push_back(k);
    for (const auto& [input, ks] : termsOfInput) {
        std::vector<double> values;
        for (std::size_t k : ks) values.push_back(tau_s[k]);
        std::sort(values.begin(), values.end());
        for (std::size_t i = 0; i < ks.size(); ++i) tau_s[ks[i]] = values[i];
    }
    return tau_s;
}

Eigen::MatrixXd LaggedRegression::jacobian(std::span<const LagCase> cases, const Eigen::MatrixXd& X,
                                           const Eigen::VectorXd& dx) const {
    const Eigen::Index K = Eigen::Index(m_terms.size());
    Eigen::MatrixXd J(X.rows(), K + X.cols());
    J.rightCols(X.cols()) = X;
    // Only term k's response depends on τ_k; it enters scaled by the term's gain.
    for (Eigen::Index k = 0; k < K; ++k) {
        const double tau = m_tau_s[std::size_t(k)];
        const Eigen::VectorXd slope =
            (termResponse(cases, std::size_t(k), tau * std::exp(kLogTauStep)) -
             termResponse(cases, std::size_t(k), tau * std::exp(-kLogTauStep))) /
            (2 * kLogTauStep);
        Eigen::VectorXd gain = Eigen::VectorXd::Constant(X.rows(), m_gains[k]);
        if (m_position_dependent) gain += m_gains[K + k] * dx;
        J.col(k) = slope.cwiseProduct(gain);
    }
    return J;
}

FitSummary LaggedRegression::fit(const std::vector<LagCase>& cases,
                                 const std::vector<Eigen::VectorXd>& observed,
                                 bool positionDependent) {
    m_position_dependent = positionDependent;
    validate(cases, observed);
    std::vector<Eigen::VectorXd> dxParts;
    for (const LagCase& c : cases)
        dxParts.push_back(positionDependent ? c.dx
                                            : Eigen::VectorXd::Zero(Eigen::Index(c.time_s.size())));
    const Eigen::VectorXd y = stacked(observed), dx = stacked(dxParts);
    const std::size_t K = m_terms.size();
    const Eigen::Index parameterCount = Eigen::Index(K) * (positionDependent ? 3 : 2);
    if (y.size() <= parameterCount)
        throw ModelError(QStringLiteral("%1 training observations are too few for %2 parameters")
                             .arg(y.size())
                             .arg(parameterCount));

    const double lo = std::log(m_options.min_tau_s), hi = std::log(m_options.max_tau_s);
    // Variable projection: for given τ the gains are a linear least squares,
    // so Ceres searches log τ only (bounded to the grid's range), on the
    // residual left after the gains are solved for.
    auto residuals = [&](const double* logTau, double* r) {
        std::vector<double> tau(K);
        for (std::size_t k = 0; k < K; ++k) tau[k] = std::exp(std::clamp(logTau[k], lo, hi));
        const Eigen::MatrixXd X = design(responses(cases, tau), dx);
        Eigen::Map<Eigen::VectorXd>(r, y.size()) = y - X * solveLeastSquares(X, y).coefficients;
        return true;
    };
    const std::vector<double> start = gridSearch(cases, dx, y);
    std::vector<double> logTau(K);
    for (std::size_t k = 0; k < K; ++k) logTau[k] = std::log(start[k]);
    ceres::Problem problem;
    problem.AddResidualBlock(numericCost<ceres::CENTRAL>(residuals, int(K), int(y.size())), nullptr,
                             logTau.data());
    for (int k = 0; k < int(K); ++k) {
        problem.SetParameterLowerBound(logTau.data(), k, lo);
        problem.SetParameterUpperBound(logTau.data(), k, hi);
    }
    ceres::Solver::Options solverOptions;
    solverOptions.linear_solver_type = ceres::DENSE_QR;
    solverOptions.logging_type = ceres::SILENT;
    ceres::Solver::Summary refined;
    ceres::Solve(solverOptions, &problem, &refined);

    std::vector<double> tau(K);
    for (std::size_t k = 0; k < K; ++k) tau[k] = std::exp(logTau[k]);
    m_tau_s = sortedPerInput(tau);
    const Eigen::MatrixXd X = design(responses(cases, m_tau_s), dx);
    const LeastSquaresFit linear = solveLeastSquares(X, y);
    m_gains = linear.coefficients;
    const Eigen::VectorXd sigma = parameterSigma(jacobian(cases, X, dx), linear.rss);

    FitSummary summary;
    summary.iterations = int(refined.iterations.size());
    const Eigen::Index n = Eigen::Index(K);
    for (Eigen::Index k = 0; k < n; ++k) {
        const LagTerm& term = m_terms[std::size_t(k)];
        const double tau = m_tau_s[std::size_t(k)];
        summary.parameters[term.name + QStringLiteral(".tau")] = {tau, tau * sigma[k],
                                                                  QStringLiteral("s")};
        summary.parameters[term.name + QStringLiteral(".a")] = {m_gains[k], sigma[n + k],
                                                                gainUnit(term.input_unit, false)};
        if (positionDependent)
            summary.parameters[term.name + QStringLiteral(".b")] = {
                m_gains[n + k], sigma[2 * n + k], gainUnit(term.input_unit, true)};
        if (tau <= m_options.min_tau_s * 1.001 || tau >= m_options.max_tau_s * 0.999)
            summary.notes << QStringLiteral(
                                 "the time constant of '%1' sits at the search bound "
                                 "(%2 s): the training runs do not pin it down")
                                 .arg(term.name, messageNumber(tau));
    }
    if (refined.termination_type != ceres::CONVERGENCE)
        summary.notes << QStringLiteral(
                             "the time-constant search stopped after %1 iterations "
                             "without converging: %2")
                             .arg(refined.iterations.size())
                             .arg(QString::fromStdString(refined.message));
    return summary;
}

Eigen::VectorXd LaggedRegression::predict(const LagCase& c) const {
    const Eigen::VectorXd dx =
        m_position_dependent ? c.dx : Eigen::VectorXd::Zero(Eigen::Index(c.time_s.size()));
    return design(responses(std::span<const LagCase>(&c, 1), m_tau_s), dx) * m_gains;
}

}  // namespace driftlab::models
