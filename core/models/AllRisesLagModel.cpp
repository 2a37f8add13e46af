#include "core/models/AllRisesLagModel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/models/CrossValidation.h"
#include "core/models/DynamicRegressionSearch.h"
#include "core/models/LeastSquares.h"
#include "core/models/ModelError.h"
#include "core/models/RunDataAccess.h"

namespace driftlab::models {
namespace {

/// The run with every k-th observation, about `rows` of them: 5 s samples
/// over hours add time to the search, not information.
RunData thinned(const RunData& run, int rows) {
    RunData part = run;
    const std::size_t step = std::max<std::size_t>(1, run.observations.size() / std::size_t(rows));
    part.observations.clear();
    for (std::size_t i = 0; i < run.observations.size(); i += step)
        part.observations.push_back(run.observations[i]);
    return part;
}

std::vector<double> timesOf(const std::vector<PredictionPoint>& at) {
    std::vector<double> times;
    for (const PredictionPoint& p : at) times.push_back(p.time_s);
    return times;
}

/// [rises, lag (when not empty)] with their position gains beside them for a
/// positioning error (`dx` not empty), else with an offset.
Eigen::MatrixXd allRisesDesign(const Eigen::MatrixXd& rises, const Eigen::VectorXd& lag,
                               const Eigen::VectorXd& dx) {
    Eigen::MatrixXd F(rises.rows(), rises.cols() + (lag.size() > 0 ? 1 : 0));
    F.leftCols(rises.cols()) = rises;
    if (lag.size() > 0) F.col(rises.cols()) = lag;
    if (dx.size() > 0) return withPositionGain(F, dx);
    Eigen::MatrixXd X(F.rows(), F.cols() + 1);
    X << F, Eigen::VectorXd::Ones(F.rows());
    return X;
}

}  // namespace

AllRisesLagModel::AllRisesLagModel(AllRisesLagOptions options) : options_(options) {}

QString AllRisesLagModel::describe() const {
    return QStringLiteral(
        "Least squares on every temperature rise, plus one sensor's rise through a "
        "first-order lag, the sensor and its time constant chosen by cross-validation over "
        "the training runs: many sensors give the unsensed parts statically, and the lag "
        "follows the one that trails them all.");
}

Eigen::MatrixXd AllRisesLagModel::design(const RunData& run, const std::vector<PredictionPoint>& at,
                                         int lagged, double tau_s) const {
    Eigen::VectorXd lag;
    if (lagged >= 0)
        lag = lagResponse(arx::riseInput(run, channels_[qsizetype(lagged)], arx::lastTime(at)),
                          tau_s, timesOf(at));
    const Eigen::VectorXd dx =
        run.positionDependent() ? positionsFromFixedEnd(run, at) : Eigen::VectorXd();
    return allRisesDesign(risesAt(run, channels_, at), lag, dx);
}

FitSummary AllRisesLagModel::fitRuns(const std::vector<RunData>& training) {
    if (!(options_.min_tau_s > 0) || !(options_.max_tau_s > options_.min_tau_s) ||
        !(options_.tau_step > 1))
        throw ModelError(QStringLiteral(
            "model 'arx-all' needs a time-constant grid with 0 < min < max and a step above 1"));
    FitSummary summary;
    channels_.clear();
    lagged_ = -1;
    tau_s_ = 0;
    const QStringList unlogged = unloggedChannels(training);
    if (!unlogged.isEmpty())
        summary.notes << QStringLiteral("not logged in the training runs: %1")
                             .arg(unlogged.join(QStringLiteral(", ")));
    for (const TemperatureRise& channel : training.front().temperatures) {
        if (unlogged.contains(channel.channel_id)) continue;
        try {
            for (const RunData& run : training)
                risesAt(run, {channel.channel_id}, run.observationPoints());
            channels_ << channel.channel_id;
        } catch (const ModelError& e) {
            summary.notes << QStringLiteral("left out: %1").arg(e.message);
        }
    }
    if (channels_.isEmpty())
        throw ModelError(QStringLiteral("model 'arx-all' has no usable temperature channel (%1)")
                             .arg(summary.notes.join(QStringLiteral("; "))));

    // The lag's candidates: a channel within its noise lagged by hours
    // becomes a slow wander a fit can match by chance (as for `arx`).
    std::vector<std::pair<int, double>> candidates{{-1, 0.0}};
    for (int j = 0; j < int(channels_.size()); ++j) {
        if (!arx::risesAboveItsNoise(training, channels_[j])) continue;
        for (double tau = options_.min_tau_s; tau <= options_.max_tau_s * 1.0001;
             tau *= options_.tau_step)
            candidates.push_back({j, tau});
    }
    std::vector<RunData> search;
    for (const RunData& run : training)
        search.push_back(thinned(run, options_.search_rows_per_run));
    const std::vector<int> folds = crossValidationFolds(search, options_.time_blocks);
    const Eigen::VectorXd y = stackRows(search, &RunData::observedErrors);
    // What every candidate shares, computed once: the rises, the positions,
    // and each sensor's rise as a lag input (only the lag differs).
    const bool positionDependent = training.front().positionDependent();
    const Eigen::MatrixXd everyRise = stackRows(search, [&](const RunData& run) {
        return risesAt(run, channels_, run.observationPoints());
    });
    Eigen::VectorXd dx;  // empty for a drift channel
    if (positionDependent)
        dx = stackRows(search, [](const RunData& run) {
            return positionsFromFixedEnd(run, run.observationPoints());
        });
    std::vector<std::vector<PiecewiseInput>> lagInputs(std::size_t(channels_.size()));
    auto lagColumn = [&](int j, double tau_s) {
        std::vector<PiecewiseInput>& inputs = lagInputs[std::size_t(j)];
        if (inputs.empty())
            for (const RunData& run : search)
                inputs.push_back(
                    arx::riseInput(run, channels_[j], arx::lastTime(run.observationPoints())));
        Eigen::VectorXd lag(everyRise.rows());
        Eigen::Index at = 0;
        for (std::size_t r = 0; r < search.size(); ++r) {
            const Eigen::VectorXd part =
                lagResponse(inputs[r], tau_s, timesOf(search[r].observationPoints()));
            lag.segment(at, part.size()) = part;
            at += part.size();
        }
        return lag;
    };
    double best = std::numeric_limits<double>::infinity(), withoutLag = best;
    for (const auto& [j, tau] : candidates) {
        if (cancelRequested()) throw ModelError(QStringLiteral("model 'arx-all': fit cancelled"));
        const double cv = crossValidatedRms(
            allRisesDesign(everyRise, j >= 0 ? lagColumn(j, tau) : Eigen::VectorXd(), dx), y,
            folds);
        if (j < 0) withoutLag = cv;
        if (cv < best) {
            best = cv;
            lagged_ = j;
            tau_s_ = tau;
        }
    }
    // A lag must earn its place, as a further sensor in `mlr` must: a lower
    // cross-validated RMS by 2 % (a difference at rounding is none).
    if (simplestNearBest({withoutLag, best}) == 0) {
        best = withoutLag;
        lagged_ = -1;
        tau_s_ = 0;
    }
    if (!std::isfinite(best))
        throw ModelError(QStringLiteral("model 'arx-all': the training runs are too few to "
                                        "cross-validate every rise (%1 channels)")
                             .arg(channels_.size()));

    const Eigen::MatrixXd X = stackRows(training, [&](const RunData& run) {
        return design(run, run.observationPoints(), lagged_, tau_s_);
    });
    const Eigen::VectorXd observed = stackRows(training, &RunData::observedErrors);
    const LeastSquaresFit fit = solveLeastSquares(X, observed);
    coefficients_ = fit.coefficients;

    // Columns: every rise, the lagged rise, then their position gains or the offset.
    const auto rises = Eigen::Index(channels_.size());
    const Eigen::Index features = rises + (lagged_ >= 0 ? 1 : 0);
    auto put = [&](const QString& key, Eigen::Index column, const QString& unit) {
        summary.parameters[key] = {coefficients_[column], fit.sigma[column], unit};
    };
    for (Eigen::Index k = 0; k < rises; ++k) {
        put(channels_[k] + QStringLiteral(".a"), k, QStringLiteral("µm/K"));
        if (positionDependent)
            put(channels_[k] + QStringLiteral(".b"), features + k, QStringLiteral("µm/(K·mm)"));
    }
    if (lagged_ >= 0) {
        const QString& lag = channels_[qsizetype(lagged_)];
        put(lag + QStringLiteral(".a_lag"), rises, QStringLiteral("µm/K"));
        if (positionDependent)
            put(lag + QStringLiteral(".b_lag"), features + rises, QStringLiteral("µm/(K·mm)"));
        // The grid step sets how well τ is known; no 1σ is claimed for it.
        summary.parameters[lag + QStringLiteral(".tau")] = {
            tau_s_, std::numeric_limits<double>::quiet_NaN(), QStringLiteral("s")};
    }
    if (!positionDependent) put(QStringLiteral("c"), features, QStringLiteral("µm"));
    summary.metrics[QStringLiteral("cv_rms_um")] = best;
    summary.metrics[QStringLiteral("r2")] = rSquared(fit.rss, observed);
    summary.notes << (lagged_ >= 0
                          ? QStringLiteral("every rise (%1 channels), and %2 through a "
                                           "lag of %3, by cross-validation (RMS %4 µm; "
                                           "%5 µm without the lag)")
                                .arg(channels_.size())
                                .arg(channels_[qsizetype(lagged_)], arx::minutesOrHours(tau_s_))
                                .arg(best, 0, 'g', 3)
                                .arg(withoutLag, 0, 'g', 3)
                          : QStringLiteral("every rise (%1 channels); no lagged rise "
                                           "lowered the cross-validated RMS by 2 % (%2 µm)")
                                .arg(channels_.size())
                                .arg(best, 0, 'g', 3));
    summary.inputs = channels_;
    return summary;
}

Eigen::VectorXd AllRisesLagModel::predictRun(const RunData& run,
                                             const std::vector<PredictionPoint>& at) const {
    return design(run, at, lagged_, tau_s_) * coefficients_;
}

}  // namespace driftlab::models
