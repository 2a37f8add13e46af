#include "core/models/LaggedSensorsSearch.h"

#include <algorithm>
#include <cmath>

#include "core/models/CrossValidation.h"
#include "core/models/LeastSquares.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models::arx {

namespace {

/// The rise at the signal's first sample: a straight line through the first
/// reference window, at its start. The rise is zero at the window's median,
/// half a window into the run; a lag starts at rest where its input starts,
/// and a part that heats from the run's first second would otherwise start
/// its lagged node half a window's rise away from it.
double riseAtStart(const Signal& rise, double window_s) {
    Eigen::Index n = 0;
    while (std::size_t(n) < rise.time_s.size() &&
           rise.time_s[std::size_t(n)] - rise.time_s.front() <= window_s)
        ++n;
    if (n < 3) return rise.value.front();
    Eigen::MatrixXd X(n, 2);
    X.col(0).setOnes();
    for (Eigen::Index i = 0; i < n; ++i)
        X(i, 1) = rise.time_s[std::size_t(i)] - rise.time_s.front();
    const LeastSquaresFit line =
        solveLeastSquares(X, Eigen::Map<const Eigen::VectorXd>(rise.value.data(), n));
    return line.full_rank ? line.coefficients[0] : rise.value.front();
}

}  // namespace

QString minutesOrHours(double tau_s) {
    return tau_s >= 5400 ? QStringLiteral("%1 h").arg(tau_s / 3600, 0, 'f', 1)
                         : QStringLiteral("%1 min").arg(tau_s / 60, 0, 'f', 0);
}

bool risesAboveItsNoise(const std::vector<RunData>& training, const QString& channel) {
    for (const RunData& run : training)
        for (const TemperatureRise& t : run.temperatures) {
            if (t.channel_id != channel) continue;
            double squares = 0, lo = INFINITY, hi = -INFINITY;
            std::size_t steps = 0;
            const std::vector<double>& v = t.rise_K.value;
            for (std::size_t i = 0; i < v.size(); ++i) {
                if (!std::isfinite(v[i])) continue;
                lo = std::min(lo, v[i]);
                hi = std::max(hi, v[i]);
                if (i > 0 && std::isfinite(v[i - 1])) {
                    squares += (v[i] - v[i - 1]) * (v[i] - v[i - 1]);
                    ++steps;
                }
            }
            if (steps == 0) continue;
            // White noise σ gives differences of RMS σ·√2.
            const double noise_K = std::max(std::sqrt(squares / double(steps) / 2), 1e-3);
            if (hi - lo > 10 * noise_K) return true;
        }
    return false;
}

PiecewiseInput riseInput(const RunData& run, const QString& channel) {
    for (const TemperatureRise& t : run.temperatures) {
        if (t.channel_id != channel) continue;
        requireCoverage(run, t.rise_K);
        const std::vector<double>& v = t.rise_K.value;
        const double start = riseAtStart(t.rise_K, run.reference_window_s);
        PiecewiseInput input{t.rise_K.time_s, v};
        for (std::size_t i = 0; i < v.size(); ++i)
            input.value[i] = (i + 1 < v.size() ? 0.5 * (v[i] + v[i + 1]) : v[i]) - start;
        return input;
    }
    throw ModelError(
        QStringLiteral("run '%1' has no temperature channel '%2'").arg(run.run_id, channel));
}

double lastTime(const std::vector<PredictionPoint>& at) {
    double last = 0;
    for (const PredictionPoint& p : at) last = std::max(last, p.time_s);
    return last;
}

std::vector<double> timesOf(const std::vector<PredictionPoint>& at) {
    std::vector<double> times;
    times.reserve(at.size());
    for (const PredictionPoint& p : at) times.push_back(p.time_s);
    return times;
}

Eigen::MatrixXd designOf(const Eigen::MatrixXd& features, const Eigen::VectorXd& dx,
                         bool positionDependent) {
    return positionDependent ? withPositionGain(features, dx) : features;
}

Eigen::MatrixXd withRunZeros(const Eigen::MatrixXd& X, const std::vector<int>& runOfRow, int runs) {
    Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(X.rows(), X.cols() + runs);
    Z.leftCols(X.cols()) = X;
    for (Eigen::Index i = 0; i < X.rows(); ++i) Z(i, X.cols() + runOfRow[std::size_t(i)]) = 1;
    return Z;
}

QStringList usableChannels(const std::vector<RunData>& training, const QString& model,
                           bool aboveNoise, FitSummary& summary) {
    QStringList usable;
    const QStringList unlogged = unloggedChannels(training);
    if (!unlogged.isEmpty())
        summary.notes << QStringLiteral("not logged in the training runs: %1")
                             .arg(unlogged.join(QStringLiteral(", ")));
    for (const TemperatureRise& channel : training.front().temperatures) {
        if (unlogged.contains(channel.channel_id)) continue;
        if (aboveNoise && !risesAboveItsNoise(training, channel.channel_id)) {
            summary.notes
                << QStringLiteral("left out: %1 stays within its noise").arg(channel.channel_id);
            continue;
        }
        try {
            for (const RunData& run : training) {
                const std::vector<PredictionPoint> at = run.observationPoints();
                risesAt(run, {channel.channel_id}, at);
                riseInput(run, channel.channel_id);
            }
            usable << channel.channel_id;
        } catch (const ModelError& e) {
            summary.notes << QStringLiteral("left out: %1").arg(e.message);
        }
    }
    if (usable.isEmpty())
        throw ModelError(QStringLiteral("model '%1' has no usable temperature channel (%2)")
                             .arg(model, summary.notes.join(QStringLiteral("; "))));
    return usable;
}

Eigen::MatrixXd withZerosOfTheirRuns(const Eigen::MatrixXd& X, const std::vector<int>& runOfRow,
                                     const std::vector<Eigen::Index>& rows) {
    std::vector<int> compact(rows.size()), seen;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const int run = runOfRow[std::size_t(rows[i])];
        auto at = std::find(seen.begin(), seen.end(), run);
        if (at == seen.end()) at = seen.insert(seen.end(), run);
        compact[i] = int(at - seen.begin());
    }
    return withRunZeros(X, compact, int(seen.size()));
}

void reportRunZeros(FitSummary& summary, const LeastSquaresFit& fit, Eigen::Index first,
                    const std::vector<RunData>& training, bool commonZero) {
    double variance = 0;
    for (std::size_t r = 0; r < training.size(); ++r) {
        const Eigen::Index z = first + Eigen::Index(r);
        summary.parameters[QStringLiteral("zero.") + training[r].run_id] = {
            fit.coefficients[z], fit.sigma[z], QStringLiteral("µm")};
        variance += fit.sigma[z] * fit.sigma[z];
    }
    if (commonZero) {
        summary.parameters[QStringLiteral("c")] = {
            fit.coefficients.segment(first, Eigen::Index(training.size())).mean(),
            std::sqrt(variance) / double(training.size()), QStringLiteral("µm")};
        summary.notes << QStringLiteral(
            "each training run's zero fitted apart; a prediction takes their mean (c), "
            "which cross-validation preferred to none");
    } else {
        summary.notes << QStringLiteral(
            "each training run's zero fitted apart; a prediction takes none (its inputs "
            "are zero where the drift's zero was taken), which cross-validation "
            "preferred to their mean");
    }
}

SetScore crossValidatedWithRunZeros(const Eigen::MatrixXd& F, const Eigen::VectorXd& y,
                                    const std::vector<int>& folds,
                                    const std::vector<int>& runOfRow) {
    const int foldCount = folds.empty() ? 0 : *std::max_element(folds.begin(), folds.end()) + 1;
    double bare = 0, shifted = 0;
    for (int f = 0; f < foldCount; ++f) {
        std::vector<Eigen::Index> train, test;
        for (std::size_t i = 0; i < folds.size(); ++i)
            (folds[i] == f ? test : train).push_back(Eigen::Index(i));
        if (test.empty()) continue;
        const Eigen::MatrixXd X = withZerosOfTheirRuns(F(train, Eigen::all), runOfRow, train);
        if (X.rows() <= X.cols()) return {};
        const LeastSquaresFit fit = solveLeastSquares(X, y(train));
        if (!fit.full_rank) return {};
        const Eigen::VectorXd residual =
            y(test) - F(test, Eigen::all) * fit.coefficients.head(F.cols());
        bare += residual.squaredNorm();
        const double zero = fit.coefficients.tail(X.cols() - F.cols()).mean();
        shifted += (residual.array() - zero).matrix().squaredNorm();
    }
    const auto n = double(y.size());
    if (shifted < bare) return {std::sqrt(shifted / n), true};
    return {std::sqrt(bare / n), false};
}

InputSearch::InputSearch(const std::vector<RunData>& training, const QStringList& candidates,
                         const LaggedSensorsOptions& options)
    : m_positionDependent(training.front().positionDependent()) {
    const double lo = std::log(options.min_tau_s), hi = std::log(options.max_tau_s);
    for (int g = 0; g < options.grid_points; ++g)
        m_grid.push_back(std::exp(lo + (hi - lo) * g / (options.grid_points - 1)));
    const std::vector<int> allFolds = crossValidationFolds(training, options.time_blocks);
    std::size_t offset = 0;
    int runIndex = 0;
    std::vector<Eigen::VectorXd> raw(std::size_t(candidates.size())),
        lagged(std::size_t(candidates.size()) * m_grid.size());
    std::vector<double> ys, dxs;
    for (const RunData& run : training) {
        const std::vector<PredictionPoint> all = run.observationPoints();
        const std::size_t stride =
            std::max<std::size_t>(1, all.size() / std::size_t(options.search_rows_per_run));
        std::vector<PredictionPoint> kept;
        for (std::size_t i = 0; i < all.size(); i += stride) {
            kept.push_back(all[i]);
            ys.push_back(run.observations[i].error_um);
            dxs.push_back(all[i].position_mm - run.fixedEnd_mm());
            m_folds.push_back(allFolds[offset + i]);
            m_runOf.push_back(runIndex);
        }
        offset += all.size();
        ++runIndex;
        const std::vector<double> times = timesOf(kept);
        for (qsizetype j = 0; j < candidates.size(); ++j) {
            append(raw[std::size_t(j)], risesAt(run, {candidates[j]}, kept).col(0));
            const PiecewiseInput input = riseInput(run, candidates[j]);
            for (std::size_t g = 0; g < m_grid.size(); ++g)
                append(lagged[std::size_t(j) * m_grid.size() + g],
                       lagResponse(input, m_grid[g], times));
        }
    }
    y_ = Eigen::Map<Eigen::VectorXd>(ys.data(), Eigen::Index(ys.size()));
    m_dx = Eigen::Map<Eigen::VectorXd>(dxs.data(), Eigen::Index(dxs.size()));
    m_raw = std::move(raw);
    m_lagged = std::move(lagged);
    m_foldCount = *std::max_element(m_folds.begin(), m_folds.end()) + 1;
}

std::pair<std::vector<int>, double> InputSearch::fitTaus(const std::vector<int>& chosen,
                                                         int heldOut) const {
    const std::vector<Eigen::Index> rows = rowsOutside(heldOut);
    std::vector<int> index(chosen.size(), int(m_grid.size()) / 2);
    double best = rss(chosen, index, rows);
    for (int sweep = 0; sweep < 4; ++sweep) {
        bool moved = false;
        for (std::size_t k = 0; k < chosen.size(); ++k) {
            std::vector<int> trial = index;
            for (int g = 0; g < int(m_grid.size()); ++g) {
                trial[k] = g;
                const double r = rss(chosen, trial, rows);
                if (r < best * (1 - 1e-9)) {
                    best = r;
                    index[k] = g;
                    moved = true;
                }
            }
        }
        if (!moved) break;
    }
    return {index, best};
}

SetScore InputSearch::crossValidated(const std::vector<int>& chosen) const {
    double bare = 0, shifted = 0;
    for (int f = 0; f < m_foldCount; ++f) {
        const auto [index, trainRss] = fitTaus(chosen, f);
        if (!std::isfinite(trainRss)) return {};
        const std::vector<Eigen::Index> train = rowsOutside(f), test = rowsIn(f);
        const LeastSquaresFit fit = solveLeastSquares(fitDesign(chosen, index, train), y_(train));
        if (!fit.full_rank) return {};
        const Eigen::MatrixXd X = design(chosen, index, test);
        const Eigen::VectorXd residual = y_(test) - X * fit.coefficients.head(X.cols());
        bare += residual.squaredNorm();
        if (m_positionDependent) continue;
        const double zero = fit.coefficients.tail(fit.coefficients.size() - X.cols()).mean();
        shifted += (residual.array() - zero).matrix().squaredNorm();
    }
    const auto n = double(y_.size());
    if (!m_positionDependent && shifted < bare) return {std::sqrt(shifted / n), true};
    return {std::sqrt(bare / n), false};
}

void InputSearch::append(Eigen::VectorXd& to, const Eigen::VectorXd& part) {
    Eigen::VectorXd joined(to.size() + part.size());
    joined << to, part;
    to = std::move(joined);
}

std::vector<Eigen::Index> InputSearch::rowsOutside(int fold) const {
    std::vector<Eigen::Index> rows;
    for (std::size_t i = 0; i < m_folds.size(); ++i)
        if (m_folds[i] != fold) rows.push_back(Eigen::Index(i));
    return rows;
}

std::vector<Eigen::Index> InputSearch::rowsIn(int fold) const {
    std::vector<Eigen::Index> rows;
    for (std::size_t i = 0; i < m_folds.size(); ++i)
        if (m_folds[i] == fold) rows.push_back(Eigen::Index(i));
    return rows;
}

Eigen::MatrixXd InputSearch::design(const std::vector<int>& chosen, const std::vector<int>& index,
                                    const std::vector<Eigen::Index>& rows) const {
    Eigen::MatrixXd F(Eigen::Index(rows.size()), 2 * Eigen::Index(chosen.size()));
    for (std::size_t k = 0; k < chosen.size(); ++k) {
        const std::size_t j = std::size_t(chosen[k]);
        F.col(2 * Eigen::Index(k)) = m_raw[j](rows);
        F.col(2 * Eigen::Index(k) + 1) = m_lagged[j * m_grid.size() + std::size_t(index[k])](rows);
    }
    return designOf(F, m_dx(rows), m_positionDependent);
}

Eigen::MatrixXd InputSearch::fitDesign(const std::vector<int>& chosen,
                                       const std::vector<int>& index,
                                       const std::vector<Eigen::Index>& rows) const {
    const Eigen::MatrixXd X = design(chosen, index, rows);
    return m_positionDependent ? X : withZerosOfTheirRuns(X, m_runOf, rows);
}

double InputSearch::rss(const std::vector<int>& chosen, const std::vector<int>& index,
                        const std::vector<Eigen::Index>& rows) const {
    const Eigen::MatrixXd X = fitDesign(chosen, index, rows);
    if (X.rows() <= X.cols()) return kInfinity;
    return solveLeastSquares(X, y_(rows)).rss;
}

}  // namespace driftlab::models::arx
