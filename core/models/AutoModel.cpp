#include "core/models/AutoModel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/models/ModelError.h"
#include "core/models/ModelFactory.h"
#include "core/models/NoCompensationModel.h"

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

}  // namespace

QString AutoModel::describe() const {
    return QStringLiteral(
        "Chooses the model family and its inputs by cross-validation over the training runs "
        "only (each run left out in turn, and every run's last 30 % of time), refits the "
        "choice on all of them and reports every family's score; no compensation is always "
        "a candidate.");
}

FitSummary AutoModel::fitRuns(const std::vector<RunData>& training) {
    chosen_.clear();
    validation_ = {};
    const std::vector<ValidationFold> folds = validationFolds(training);
    const auto cancelled = [this] { return cancelRequested(); };
    std::vector<HeldOutPredictions> predictions;
    std::vector<double> scores, standardErrors;
    QStringList scored, failed;
    for (const QString& family : familiesSimplestFirst()) {
        try {
            predictions.push_back(crossValidatedPredictions(family, folds, cancelled));
            scores.push_back(predictions.back().rms_um());
            standardErrors.push_back(predictions.back().standard_error_um());
            scored << QStringLiteral("%1 %2 µm").arg(family).arg(scores.back(), 0, 'g', 3);
        } catch (const ModelError& e) {
            if (cancelRequested()) throw;
            predictions.emplace_back();
            scores.push_back(std::numeric_limits<double>::infinity());
            standardErrors.push_back(0);
            failed << QStringLiteral("%1 (%2)").arg(family, e.message);
        }
    }
    const double best = *std::min_element(scores.begin(), scores.end());
    if (!std::isfinite(best))
        throw ModelError(QStringLiteral("model 'auto': no model family can be fitted and "
                                        "cross-validated on these runs: %1")
                             .arg(failed.join(QStringLiteral("; "))));
    const auto bestAt = std::size_t(std::find(scores.begin(), scores.end(), best) - scores.begin());
    // Every family predicts the same held-out readings: no compensation's
    // score is their own RMS.
    const double none = predictions[bestAt].none_rms_um();
    // The families within one standard error of the best score (Hastie,
    // Tibshirani & Friedman, §7.10): a few training runs rank them by chance.
    // Their mean varies less than any one of them.
    const double window = best * (1 + std::max(0.02, best > 0 ? standardErrors[bestAt] / best : 0));
    std::vector<std::size_t> members;
    for (std::size_t k = 0; k < scores.size(); ++k)
        if (scores[k] <= window) members.push_back(k);
    std::stable_sort(members.begin(), members.end(),
                     [&](std::size_t a, std::size_t b) { return scores[a] < scores[b]; });
    // No harm: what auto predicts with must do better than no compensation
    // on the same readings; else the best family alone; else nothing.
    std::vector<HeldOutPredictions> chosenPredictions;
    for (std::size_t k : members) chosenPredictions.push_back(predictions[k]);
    if (members.size() > 1 && !(meanPredictions(chosenPredictions).rms_um() < none)) {
        members = {bestAt};
        chosenPredictions = {predictions[bestAt]};
    }
    if (!(best < none)) {
        members.clear();
        chosenPredictions.clear();
    }

    std::vector<FitSummary> fits;
    for (std::size_t k : members) {
        std::unique_ptr<ThermalErrorModel> model = makeModel(familiesSimplestFirst()[qsizetype(k)]);
        model->setCancelCheck(cancelled);
        FitSummary fit = model->fit(training);
        if (!fit.success) throw ModelError(fit.message);
        chosen_.push_back(std::move(model));
        fits.push_back(std::move(fit));
    }
    if (members.empty()) {
        // No compensation is the best there is: its predictions are zero.
        chosen_.push_back(std::make_unique<NoCompensationModel>());
        fits.push_back(chosen_.back()->fit(training));
        HeldOutPredictions zero = predictions[bestAt];
        std::fill(zero.predicted_um.begin(), zero.predicted_um.end(), 0.0);
        chosenPredictions.push_back(std::move(zero));
    }
    validation_ = validationOf(meanPredictions(chosenPredictions),
                               training.front().positionDependent(), training.size());
    FitSummary summary = fits.size() == 1 ? fits.front() : combined(fits);

    summary.metrics[QStringLiteral("auto_cv_rms_um.none")] = none;
    for (std::size_t k = 0; k < scores.size(); ++k)
        if (std::isfinite(scores[k]))
            summary.metrics[QStringLiteral("auto_cv_rms_um.") +
                            familiesSimplestFirst()[qsizetype(k)]] = scores[k];
    const QString how = describeValidationFolds(training.size());
    const QString listed =
        QStringLiteral("no compensation %1 µm, ").arg(none, 0, 'g', 3) + scored.join(", ");
    QStringList notes;
    if (members.empty())
        notes << QStringLiteral(
                     "auto chose no compensation: no model family does better than none by "
                     "cross-validation over the training runs (%1): %2")
                     .arg(how, listed);
    else
        notes << QStringLiteral(
                     "auto chose %1%2 by cross-validation over the training runs "
                     "(%3): %4")
                     .arg(chosen(),
                          fits.size() > 1
                              ? QStringLiteral(" (their mean: each within one standard error "
                                               "of the best score)")
                              : QString(),
                          how, listed);
    if (!failed.isEmpty())
        notes << QStringLiteral("auto could not try: %1").arg(failed.join(QStringLiteral("; ")));
    summary.notes = notes + summary.notes;
    summary.message =
        members.empty()
            ? QStringLiteral("model 'auto' chose no compensation on %1 run(s)").arg(training.size())
            : QStringLiteral("model 'auto' chose '%1' and fitted it on %2 run(s)")
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
