#include "core/models/DynamicRegressionModel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/models/CrossValidation.h"
#include "core/models/FirstOrderLag.h"
#include "core/models/LeastSquares.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The rise as a lag input: each sample interval holds the mean of its two
/// ends, so the filtered rise is not delayed by half a sample.
PiecewiseInput riseInput(const RunData& run, const QString& channel, double until_s) {
    for (const TemperatureRise& t : run.temperatures) {
        if (t.channel_id != channel) continue;
        requireCoverage(run, t.rise_K, until_s);
        PiecewiseInput input{t.rise_K.time_s, t.rise_K.value};
        for (std::size_t i = 0; i + 1 < input.value.size(); ++i)
            input.value[i] = 0.5 * (t.rise_K.value[i] + t.rise_K.value[i + 1]);
        return input;
    }
    throw ModelError(
        QStringLiteral("run '%1' has no temperature channel '%2'").arg(run.run_id, channel));
}

/// Whether the channel's rise, over some training run, spans more than ten
/// times its noise (from successive differences, which a slow rise hardly
/// touches). A flat channel (the room thermometer of a steady room) carries no
/// heat; lagged, its noise becomes a slow wander that a fit can match by chance.
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

double lastTime(const std::vector<PredictionPoint>& at) {
    double last = 0;
    for (const PredictionPoint& p : at) last = std::max(last, p.time_s);
    return last;
}

/// Columns [ΔT, L_τ[ΔT]] per input, position-gain copies beside them for a
/// positioning error, an intercept for a drift channel.
Eigen::MatrixXd designOf(const Eigen::MatrixXd& features, const Eigen::VectorXd& dx,
                         bool positionDependent) {
    if (positionDependent) return withPositionGain(features, dx);
    Eigen::MatrixXd X(features.rows(), features.cols() + 1);
    X << features, Eigen::VectorXd::Ones(features.rows());
    return X;
}

/// The search over sensors and time constants, on a thinned set of rows whose
/// features are computed once for every grid time constant.
class InputSearch {
public:
    InputSearch(const std::vector<RunData>& training, const QStringList& candidates,
                const DynamicRegressionOptions& options)
        : positionDependent_(training.front().positionDependent()) {
        const double lo = std::log(options.min_tau_s), hi = std::log(options.max_tau_s);
        for (int g = 0; g < options.grid_points; ++g)
            grid_.push_back(std::exp(lo + (hi - lo) * g / (options.grid_points - 1)));
        const std::vector<int> allFolds = crossValidationFolds(training, options.time_blocks);
        std::size_t offset = 0;
        std::vector<Eigen::VectorXd> raw(std::size_t(candidates.size())),
            lagged(std::size_t(candidates.size()) * grid_.size());
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
                folds_.push_back(allFolds[offset + i]);
            }
            offset += all.size();
            std::vector<double> times;
            for (const PredictionPoint& p : kept) times.push_back(p.time_s);
            for (qsizetype j = 0; j < candidates.size(); ++j) {
                append(raw[std::size_t(j)], risesAt(run, {candidates[j]}, kept).col(0));
                const PiecewiseInput input = riseInput(run, candidates[j], lastTime(kept));
                for (std::size_t g = 0; g < grid_.size(); ++g)
                    append(lagged[std::size_t(j) * grid_.size() + g],
                           lagResponse(input, grid_[g], times));
            }
        }
        y_ = Eigen::Map<Eigen::VectorXd>(ys.data(), Eigen::Index(ys.size()));
        dx_ = Eigen::Map<Eigen::VectorXd>(dxs.data(), Eigen::Index(dxs.size()));
        raw_ = std::move(raw);
        lagged_ = std::move(lagged);
        foldCount_ = *std::max_element(folds_.begin(), folds_.end()) + 1;
    }

    const std::vector<double>& grid() const { return grid_; }

    /// Time-constant grid indices for the sensors `chosen` fitted on the rows
    /// not in `heldOut` (−1: none), by coordinate descent; returns the RSS too.
    std::pair<std::vector<int>, double> fitTaus(const std::vector<int>& chosen, int heldOut) const {
        const std::vector<Eigen::Index> rows = rowsOutside(heldOut);
        std::vector<int> index(chosen.size(), int(grid_.size()) / 2);
        double best = rss(chosen, index, rows);
        for (int sweep = 0; sweep < 4; ++sweep) {
            bool moved = false;
            for (std::size_t k = 0; k < chosen.size(); ++k) {
                std::vector<int> trial = index;
                for (int g = 0; g < int(grid_.size()); ++g) {
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

    /// RMS of the held-out residuals, every fold refitting its time constants.
    double crossValidatedRms(const std::vector<int>& chosen) const {
        double squares = 0;
        for (int f = 0; f < foldCount_; ++f) {
            const auto [index, trainRss] = fitTaus(chosen, f);
            if (!std::isfinite(trainRss)) return kInfinity;
            const std::vector<Eigen::Index> train = rowsOutside(f), test = rowsIn(f);
            const LeastSquaresFit fit = solveLeastSquares(design(chosen, index, train), y_(train));
            if (!fit.full_rank) return kInfinity;
            squares += (y_(test) - design(chosen, index, test) * fit.coefficients).squaredNorm();
        }
        return std::sqrt(squares / double(y_.size()));
    }

private:
    static void append(Eigen::VectorXd& to, const Eigen::VectorXd& part) {
        Eigen::VectorXd joined(to.size() + part.size());
        joined << to, part;
        to = std::move(joined);
    }
    std::vector<Eigen::Index> rowsOutside(int fold) const {
        std::vector<Eigen::Index> rows;
        for (std::size_t i = 0; i < folds_.size(); ++i)
            if (folds_[i] != fold) rows.push_back(Eigen::Index(i));
        return rows;
    }
    std::vector<Eigen::Index> rowsIn(int fold) const {
        std::vector<Eigen::Index> rows;
        for (std::size_t i = 0; i < folds_.size(); ++i)
            if (folds_[i] == fold) rows.push_back(Eigen::Index(i));
        return rows;
    }
    Eigen::MatrixXd design(const std::vector<int>& chosen, const std::vector<int>& index,
                           const std::vector<Eigen::Index>& rows) const {
        Eigen::MatrixXd F(Eigen::Index(rows.size()), 2 * Eigen::Index(chosen.size()));
        for (std::size_t k = 0; k < chosen.size(); ++k) {
            const std::size_t j = std::size_t(chosen[k]);
            F.col(2 * Eigen::Index(k)) = raw_[j](rows);
            F.col(2 * Eigen::Index(k) + 1) =
                lagged_[j * grid_.size() + std::size_t(index[k])](rows);
        }
        return designOf(F, dx_(rows), positionDependent_);
    }
    double rss(const std::vector<int>& chosen, const std::vector<int>& index,
               const std::vector<Eigen::Index>& rows) const {
        const Eigen::MatrixXd X = design(chosen, index, rows);
        if (X.rows() <= X.cols()) return kInfinity;
        return solveLeastSquares(X, y_(rows)).rss;
    }

    bool positionDependent_;
    std::vector<double> grid_;
    std::vector<int> folds_;
    int foldCount_ = 0;
    Eigen::VectorXd y_, dx_;
    std::vector<Eigen::VectorXd> raw_;     ///< per candidate
    std::vector<Eigen::VectorXd> lagged_;  ///< per candidate and grid τ
};

QString minutes(double tau_s) {
    return tau_s >= 5400 ? QStringLiteral("%1 h").arg(tau_s / 3600, 0, 'f', 1)
                         : QStringLiteral("%1 min").arg(tau_s / 60, 0, 'f', 0);
}

}  // namespace

DynamicRegressionModel::DynamicRegressionModel(DynamicRegressionOptions options)
    : options_(options) {}

QString DynamicRegressionModel::describe() const {
    return QStringLiteral(
               "Dynamic regression: up to %1 sensors chosen by cross-validation over the "
               "training runs, each entering with its current temperature rise and with its "
               "rise through a first-order lag of fitted time constant, so that drift which "
               "lags the sensors is followed.")
        .arg(options_.max_sensors);
}

FitSummary DynamicRegressionModel::fitRuns(const std::vector<RunData>& training) {
    if (options_.max_sensors < 1 || options_.grid_points < 2 || !(options_.min_tau_s > 0) ||
        !(options_.max_tau_s > options_.min_tau_s))
        throw ModelError(
            QStringLiteral("model 'arx' needs at least one sensor and a time-constant "
                           "grid of 2 or more points with 0 < min < max"));
    FitSummary summary;
    QStringList candidates;
    const QStringList unlogged = unloggedChannels(training);
    if (!unlogged.isEmpty())
        summary.notes << QStringLiteral("not logged in the training runs: %1")
                             .arg(unlogged.join(QStringLiteral(", ")));
    for (const TemperatureRise& channel : training.front().temperatures) {
        if (unlogged.contains(channel.channel_id)) continue;
        if (!risesAboveItsNoise(training, channel.channel_id)) {
            summary.notes
                << QStringLiteral("left out: %1 stays within its noise").arg(channel.channel_id);
            continue;
        }
        try {
            for (const RunData& run : training) {
                const std::vector<PredictionPoint> at = run.observationPoints();
                risesAt(run, {channel.channel_id}, at);
                riseInput(run, channel.channel_id, lastTime(at));
            }
            candidates << channel.channel_id;
        } catch (const ModelError& e) {
            summary.notes << QStringLiteral("left out: %1").arg(e.message);
        }
    }
    if (candidates.isEmpty())
        throw ModelError(QStringLiteral("model 'arx' has no usable temperature channel (%1)")
                             .arg(summary.notes.join(QStringLiteral("; "))));

    // Forward selection: the sensor that most lowers the cross-validated RMS,
    // one at a time; then the simplest set nearly as good as the best.
    const InputSearch search(training, candidates, options_);
    std::vector<std::vector<int>> sets;
    std::vector<double> scores;
    std::vector<int> chosen;
    const int largest = std::min(options_.max_sensors, int(candidates.size()));
    for (int size = 1; size <= largest; ++size) {
        if (cancelRequested()) throw ModelError(QStringLiteral("model 'arx': fit cancelled"));
        double bestScore = kInfinity;
        int bestSensor = -1;
        for (int j = 0; j < int(candidates.size()); ++j) {
            if (std::find(chosen.begin(), chosen.end(), j) != chosen.end()) continue;
            std::vector<int> trial = chosen;
            trial.push_back(j);
            const double cv = search.crossValidatedRms(trial);
            if (cv < bestScore) {
                bestScore = cv;
                bestSensor = j;
            }
        }
        if (bestSensor < 0) break;
        chosen.push_back(bestSensor);
        sets.push_back(chosen);
        scores.push_back(bestScore);
    }
    // Each sensor adds three parameters, and opposed gains on correlated
    // sensors amplify their noise on motion the training runs did not show:
    // a further sensor must lower the cross-validated RMS by 10 %.
    const std::size_t pick = simplestNearBest(scores, 0.10);
    if (pick == scores.size())
        throw ModelError(
            QStringLiteral("model 'arx': the training runs are too few to "
                           "cross-validate any sensor set"));

    const std::vector<int>& set = sets[pick];
    const std::vector<int> index = search.fitTaus(set, -1).first;
    inputs_.clear();
    for (std::size_t k = 0; k < set.size(); ++k)
        inputs_.push_back({candidates[set[k]], search.grid()[std::size_t(index[k])]});

    // Gains on every observation, at the chosen time constants.
    const bool positionDependent = training.front().positionDependent();
    const Eigen::MatrixXd X = stackRows(training, [&](const RunData& run) {
        const std::vector<PredictionPoint> at = run.observationPoints();
        return designOf(DynamicRegressionModel::features(run, at), positionsFromFixedEnd(run, at),
                        positionDependent);
    });
    const Eigen::VectorXd y = stackRows(training, &RunData::observedErrors);
    const LeastSquaresFit fit = solveLeastSquares(X, y);
    coefficients_ = fit.coefficients;

    const Eigen::Index m = 2 * Eigen::Index(inputs_.size());
    QStringList described;
    for (std::size_t k = 0; k < inputs_.size(); ++k) {
        const QString& s = inputs_[k].channel;
        const Eigen::Index a = 2 * Eigen::Index(k), g = a + 1;
        // The grid step sets how well τ is known; no 1σ is claimed for it.
        summary.parameters[s + QStringLiteral(".tau")] = {
            inputs_[k].tau_s, std::numeric_limits<double>::quiet_NaN(), QStringLiteral("s")};
        summary.parameters[s + QStringLiteral(".a")] = {coefficients_[a], fit.sigma[a],
                                                        QStringLiteral("µm/K")};
        summary.parameters[s + QStringLiteral(".a_lag")] = {coefficients_[g], fit.sigma[g],
                                                            QStringLiteral("µm/K")};
        if (positionDependent) {
            summary.parameters[s + QStringLiteral(".b")] = {coefficients_[m + a], fit.sigma[m + a],
                                                            QStringLiteral("µm/(K·mm)")};
            summary.parameters[s + QStringLiteral(".b_lag")] = {
                coefficients_[m + g], fit.sigma[m + g], QStringLiteral("µm/(K·mm)")};
        }
        described << QStringLiteral("%1 (lag %2)").arg(s, minutes(inputs_[k].tau_s));
        if (index[k] == 0 || index[k] + 1 == int(search.grid().size()))
            summary.notes << QStringLiteral(
                                 "the lag of %1 sits at the search bound (%2): the "
                                 "training runs do not pin it down")
                                 .arg(s, minutes(inputs_[k].tau_s));
        summary.inputs << s;
    }
    if (!positionDependent)
        summary.parameters[QStringLiteral("c")] = {coefficients_[m], fit.sigma[m],
                                                   QStringLiteral("µm")};
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

Eigen::MatrixXd DynamicRegressionModel::features(const RunData& run,
                                                 const std::vector<PredictionPoint>& at) const {
    std::vector<double> times;
    for (const PredictionPoint& p : at) times.push_back(p.time_s);
    Eigen::MatrixXd F(Eigen::Index(at.size()), 2 * Eigen::Index(inputs_.size()));
    for (std::size_t k = 0; k < inputs_.size(); ++k) {
        F.col(2 * Eigen::Index(k)) = risesAt(run, {inputs_[k].channel}, at).col(0);
        F.col(2 * Eigen::Index(k) + 1) =
            lagResponse(riseInput(run, inputs_[k].channel, lastTime(at)), inputs_[k].tau_s, times);
    }
    return F;
}

Eigen::VectorXd DynamicRegressionModel::predictRun(const RunData& run,
                                                   const std::vector<PredictionPoint>& at) const {
    return designOf(features(run, at), positionsFromFixedEnd(run, at), run.positionDependent()) *
           coefficients_;
}

}  // namespace driftlab::models
