#include "core/models/AutoModel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/models/ModelError.h"
#include "core/models/ModelFactory.h"

namespace driftlab::models {
namespace {

/// The families, simplest first: the order they are tried and reported in.
const QStringList& familiesSimplestFirst() {
    static const QStringList families{
        QStringLiteral("mlr"),          QStringLiteral("poly-position"),
        QStringLiteral("exponential"),  QStringLiteral("sensorless"),
        QStringLiteral("arx"),          QStringLiteral("arx-all"),
        QStringLiteral("heat-transfer")};
    return families;
}

/// The run with its observations before (`early`) or after 70 % of its time.
RunData timeSplit(const RunData& run, bool early) {
    double first = run.observations.front().time_s, last = first;
    for (const ErrorObservation& o : run.observations) {
        first = std::min(first, o.time_s);
        last = std::max(last, o.time_s);
    }
    const double cut = first + 0.7 * (last - first);
    RunData part = run;
    part.observations.clear();
    for (const ErrorObservation& o : run.observations)
        if ((o.time_s <= cut) == early) part.observations.push_back(o);
    return part;
}

}  // namespace

QString AutoModel::describe() const {
    return QStringLiteral(
        "Chooses the model family and its inputs by cross-validation over the training runs "
        "only (each run left out in turn, and every run's last 30 % of time), refits the "
        "choice on all of them and reports every "
        "family's score.");
}

std::vector<AutoModel::Fold> AutoModel::foldsOf(const std::vector<RunData>& training) {
    // Folds of two kinds. Each run held out in turn scores motion the fit has
    // not seen, but fits on one run fewer: with three runs a family whose
    // strength shows only once every speed programme is in the fit (every
    // rise with lags, on two runs that excite few of the heat paths) ranks
    // low there. So every run's first 70 % of time is also fitted together and
    // each run's last 30 % scored (in a warm-up and cool-down test, mostly
    // the cooling): every programme in the fit, time it has not seen. With a
    // single run that is the only fold.
    std::vector<Fold> folds;
    if (training.size() > 1) {
        for (std::size_t r = 0; r < training.size(); ++r) {
            Fold fold;
            for (std::size_t k = 0; k < training.size(); ++k)
                if (k != r) fold.fit_on.push_back(training[k]);
            fold.held_out.push_back(training[r]);
            folds.push_back(std::move(fold));
        }
    }
    Fold inTime;
    for (const RunData& run : training) {
        inTime.fit_on.push_back(timeSplit(run, true));
        RunData late = timeSplit(run, false);
        if (!late.observations.empty()) inTime.held_out.push_back(std::move(late));
    }
    if (!inTime.held_out.empty()) folds.push_back(std::move(inTime));
    return folds;
}

AutoModel::CrossValidatedScore AutoModel::crossValidatedRms(const QString& family,
                                                            const std::vector<Fold>& folds) const {
    double squares = 0;
    std::size_t count = 0;
    std::vector<double> foldMeanSquares;
    for (const Fold& fold : folds) {
        if (cancelRequested()) throw ModelError(QStringLiteral("model 'auto': fit cancelled"));
        const std::unique_ptr<ThermalErrorModel> model = makeModel(family);
        model->setCancelCheck([this] { return cancelRequested(); });
        const FitSummary fit = model->fit(fold.fit_on);
        if (!fit.success) throw ModelError(fit.message);
        for (const RunData& heldOut : fold.held_out) {
            const Prediction p = model->predict(heldOut);
            if (!p.ok()) throw ModelError(p.error);
            const Eigen::VectorXd measured = heldOut.observedErrors();
            double squaresOfRun = 0;
            for (Eigen::Index i = 0; i < measured.size(); ++i)
                squaresOfRun += std::pow(measured[i] - p.error_um[std::size_t(i)], 2);
            squares += squaresOfRun;
            count += std::size_t(measured.size());
            if (measured.size() > 0)
                foldMeanSquares.push_back(squaresOfRun / double(measured.size()));
        }
    }
    if (count == 0) throw ModelError(QStringLiteral("no observation to score on"));
    CrossValidatedScore score{std::sqrt(squares / double(count)), 0};
    // The standard error of the mean square over the folds, carried to the
    // RMS (d√m = dm / 2√m).
    const std::size_t k = foldMeanSquares.size();
    if (k > 1 && score.rms_um > 0) {
        double mean = 0, spread = 0;
        for (double m : foldMeanSquares) mean += m / double(k);
        for (double m : foldMeanSquares) spread += (m - mean) * (m - mean) / double(k - 1);
        score.standard_error_um = std::sqrt(spread / double(k)) / (2 * score.rms_um);
    }
    return score;
}

FitSummary AutoModel::fitRuns(const std::vector<RunData>& training) {
    chosen_.clear();
    std::vector<double> scores, standardErrors;
    QStringList scored, failed;
    const std::vector<Fold> folds = foldsOf(training);
    for (const QString& family : familiesSimplestFirst()) {
        try {
            const CrossValidatedScore score = crossValidatedRms(family, folds);
            scores.push_back(score.rms_um);
            standardErrors.push_back(score.standard_error_um);
            scored << QStringLiteral("%1 %2 µm").arg(family).arg(scores.back(), 0, 'g', 3);
        } catch (const ModelError& e) {
            if (cancelRequested()) throw;
            scores.push_back(std::numeric_limits<double>::infinity());
            standardErrors.push_back(0);
            failed << QStringLiteral("%1 (%2)").arg(family, e.message);
        }
    }
    // The families within one standard error of the best score (Hastie,
    // Tibshirani & Friedman, §7.10): a few training runs rank them by chance.
    // Their mean varies less than any one of them.
    const double best = *std::min_element(scores.begin(), scores.end());
    if (!std::isfinite(best))
        throw ModelError(QStringLiteral("model 'auto': no model family can be fitted and "
                                        "cross-validated on these runs: %1")
                             .arg(failed.join(QStringLiteral("; "))));
    const auto bestAt = std::size_t(std::find(scores.begin(), scores.end(), best) - scores.begin());
    const double window = best * (1 + std::max(0.02, best > 0 ? standardErrors[bestAt] / best : 0));
    std::vector<std::size_t> members;
    for (std::size_t k = 0; k < scores.size(); ++k)
        if (scores[k] <= window) members.push_back(k);
    std::stable_sort(members.begin(), members.end(),
                     [&](std::size_t a, std::size_t b) { return scores[a] < scores[b]; });

    std::vector<FitSummary> fits;
    for (std::size_t k : members) {
        std::unique_ptr<ThermalErrorModel> model = makeModel(familiesSimplestFirst()[qsizetype(k)]);
        model->setCancelCheck([this] { return cancelRequested(); });
        FitSummary fit = model->fit(training);
        if (!fit.success) throw ModelError(fit.message);
        chosen_.push_back(std::move(model));
        fits.push_back(std::move(fit));
    }
    FitSummary summary = fits.size() == 1 ? fits.front() : combined(fits);

    for (std::size_t k = 0; k < scores.size(); ++k)
        if (std::isfinite(scores[k]))
            summary.metrics[QStringLiteral("auto_cv_rms_um.") +
                            familiesSimplestFirst()[qsizetype(k)]] = scores[k];
    const QString how =
        training.size() > 1
            ? QStringLiteral(
                  "leaving each training run out in turn, and fitting every run's first "
                  "70 % to score the rest")
            : QStringLiteral("fitting the run's first 70 % and scoring the rest");
    const QString mean = fits.size() > 1
                             ? QStringLiteral(
                                   " (their mean: each within one standard error of the "
                                   "best score)")
                             : QString();
    QStringList notes{QStringLiteral("auto chose %1%2 by cross-validation over the training runs "
                                     "(%3): %4")
                          .arg(chosen(), mean, how, scored.join(QStringLiteral(", ")))};
    if (!failed.isEmpty())
        notes << QStringLiteral("auto could not try: %1").arg(failed.join(QStringLiteral("; ")));
    summary.notes = notes + summary.notes;
    summary.message = QStringLiteral("model 'auto' chose '%1' and fitted it on %2 run(s)")
                          .arg(chosen())
                          .arg(training.size());
    return summary;
}

QString AutoModel::chosen() const {
    QStringList names;
    for (const auto& model : chosen_) names << model->name();
    return names.join(QStringLiteral(" + "));
}

FitSummary AutoModel::combined(const std::vector<FitSummary>& fits) const {
    // Each family's figures under its own name: "arx/T_spindle.tau".
    FitSummary summary;
    for (std::size_t m = 0; m < fits.size(); ++m) {
        const QString family = chosen_[m]->name();
        for (const auto& [key, value] : fits[m].parameters)
            summary.parameters[family + QLatin1Char('/') + key] = value;
        for (const auto& [key, value] : fits[m].metrics)
            summary.metrics[family + QLatin1Char('/') + key] = value;
        for (const QString& input : fits[m].inputs)
            if (!summary.inputs.contains(input)) summary.inputs << input;
        for (const QString& note : fits[m].notes)
            summary.notes << family + QStringLiteral(": ") + note;
        summary.iterations += fits[m].iterations;
    }
    return summary;
}

Eigen::VectorXd AutoModel::predictRun(const RunData& run,
                                      const std::vector<PredictionPoint>& at) const {
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(Eigen::Index(at.size()));
    for (const auto& model : chosen_) {
        const Prediction p = model->predict(run, at);
        if (!p.ok()) throw ModelError(p.error);
        sum +=
            Eigen::Map<const Eigen::VectorXd>(p.error_um.data(), Eigen::Index(p.error_um.size()));
    }
    return sum / double(chosen_.size());
}

}  // namespace driftlab::models
