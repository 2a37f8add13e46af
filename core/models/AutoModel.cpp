#include "core/models/AutoModel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/models/ModelError.h"
#include "core/models/ModelFactory.h"
#include "core/models/NoCompensationModel.h"
#include "core/models/StackedCombination.h"

namespace driftlab::models {
namespace {

/// The families, simplest first: the order they are tried and reported in.
const QStringList& familiesSimplestFirst() {
    static const QStringList families{
        QStringLiteral("mlr"),         QStringLiteral("poly-position"),
        QStringLiteral("exponential"), QStringLiteral("sensorless"),
        QStringLiteral("arx"),         QStringLiteral("arx-all"),
        QStringLiteral("lsall-heat"),  QStringLiteral("ridge-heat"),
        QStringLiteral("pcr-heat"),    QStringLiteral("heat-transfer")};
    return families;
}

/// The families of one design, every rise and the spindle's heat with one
/// offset, fitted three ways.
const QStringList& shrunkenAllRises() {
    static const QStringList families{QStringLiteral("lsall-heat"), QStringLiteral("ridge-heat"),
                                      QStringLiteral("pcr-heat")};
    return families;
}

}  // namespace

QString AutoModel::describe() const {
    return QStringLiteral(
        "Combines the model families by cross-validation over the training runs only (each "
        "run left out in turn, and every run's last 30 % of time): their stacked combination "
        "(weights of at least zero summing to one, fitted to their held-out predictions) "
        "where it is 2 % better than the mean of the near-best families, else that mean; "
        "refits them on all the runs and reports every family's score and weight. No "
        "compensation is always a candidate.");
}

FitSummary AutoModel::fitRuns(const std::vector<RunData>& training) {
    m_chosen.clear();
    m_weights.clear();
    m_validation = {};
    const std::vector<ValidationFold> folds = validationFolds(training);
    const auto cancelled = [this] { return cancelRequested(); };
    // Each family's held-out predictions on the same readings; a family that
    // fails on some fold takes no part.
    std::vector<HeldOutPredictions> predictions;
    QStringList families, scored, failed;
    for (const QString& family : familiesSimplestFirst()) {
        try {
            predictions.push_back(crossValidatedPredictions(family, folds, cancelled));
            families << family;
            scored << QStringLiteral("%1 %2 µm")
                          .arg(family)
                          .arg(predictions.back().rms_um(), 0, 'g', 3);
        } catch (const ModelError& e) {
            if (cancelRequested()) throw;
            failed << QStringLiteral("%1 (%2)").arg(family, e.message);
        }
    }
    if (predictions.empty())
        throw ModelError(QStringLiteral("model 'auto': no model family can be fitted and "
                                        "cross-validated on these runs: %1")
                             .arg(failed.join(QStringLiteral("; "))));
    // Every family predicts the same held-out readings: no compensation's
    // score is their own RMS.
    const double none = predictions.front().none_rms_um();
    // The shrunken all-rises families are three fits of one design: in an
    // equal-weight mean they would count three times. They take part through
    // the stack, where a family the others already give takes no weight.
    std::vector<bool> inMean;
    for (const QString& family : families) inMean.push_back(!shrunkenAllRises().contains(family));
    const CombinationChoice choice = chooseCombination(predictions, inMean);

    std::vector<FitSummary> fits;
    for (std::size_t m = 0; m < choice.members.size(); ++m) {
        std::unique_ptr<ThermalErrorModel> model =
            makeModel(families[qsizetype(choice.members[m])]);
        model->setCancelCheck(cancelled);
        FitSummary fit = model->fit(training);
        if (!fit.success) throw ModelError(fit.message);
        m_chosen.push_back(std::move(model));
        m_weights.push_back(choice.weights[m]);
        fits.push_back(std::move(fit));
    }
    if (m_chosen.empty()) {
        // No compensation is the best there is: its predictions are zero.
        m_chosen.push_back(std::make_unique<NoCompensationModel>());
        m_weights.push_back(1.0);
        fits.push_back(m_chosen.back()->fit(training));
    }
    m_validation =
        validationOf(choice.predictions, training.front().positionDependent(), training.size());
    FitSummary summary = fits.size() == 1 ? fits.front() : combined(fits);

    summary.metrics[QStringLiteral("auto_cv_rms_um.none")] = none;
    for (qsizetype f = 0; f < families.size(); ++f)
        summary.metrics[QStringLiteral("auto_cv_rms_um.") + families[f]] =
            predictions[std::size_t(f)].rms_um();
    summary.metrics[QStringLiteral("auto_cv_rms_um.stacked")] = choice.stack_rms_um;
    if (std::isfinite(choice.mean_rms_um))
        summary.metrics[QStringLiteral("auto_cv_rms_um.mean")] = choice.mean_rms_um;
    QStringList stackWeights;
    for (qsizetype f = 0; f < families.size(); ++f)
        if (choice.stack_weights[std::size_t(f)] > 0) {
            summary.metrics[QStringLiteral("auto_stack_weight.") + families[f]] =
                choice.stack_weights[std::size_t(f)];
            stackWeights << QStringLiteral("%1 %2")
                                .arg(families[f])
                                .arg(choice.stack_weights[std::size_t(f)], 0, 'f', 2);
        }
    if (choice.kind != CombinationChoice::Kind::None) {
        summary.metrics[QStringLiteral("auto_cv_rms_um.chosen")] = m_validation.rms_um;
        for (std::size_t m = 0; m < m_chosen.size(); ++m)
            summary.metrics[QStringLiteral("auto_weight.") + m_chosen[m]->name()] = m_weights[m];
    }
    const QString how = describeValidationFolds(training.size());
    const QString listed =
        QStringLiteral("no compensation %1 µm, ").arg(none, 0, 'g', 3) + scored.join(", ");
    const QString stackSaid = QStringLiteral("stacked %1: %2 µm")
                                  .arg(stackWeights.join(QStringLiteral(", ")))
                                  .arg(choice.stack_rms_um, 0, 'g', 3);
    QStringList notes;
    switch (choice.kind) {
        case CombinationChoice::Kind::None:
            notes << QStringLiteral(
                         "auto chose no compensation: no model family does better than none by "
                         "cross-validation over the training runs (%1): %2; %3")
                         .arg(how, listed, stackSaid);
            break;
        case CombinationChoice::Kind::BestSingle:
            notes << QStringLiteral(
                         "auto chose %1 by cross-validation over the training runs (%2; no "
                         "combination did better than no compensation): %3; %4")
                         .arg(chosen(), how, listed, stackSaid);
            break;
        case CombinationChoice::Kind::Mean:
            notes << QStringLiteral(
                         "auto chose %1%2 by cross-validation over the training runs (%3): "
                         "%4; %5, not 2 % below the mean's %6 µm")
                         .arg(chosen(),
                              m_chosen.size() > 1
                                  ? QStringLiteral(" (their mean: each within one standard "
                                                   "error of the best score)")
                                  : QString(),
                              how, listed, stackSaid)
                         .arg(choice.mean_rms_um, 0, 'g', 3);
            break;
        case CombinationChoice::Kind::Stacked: {
            QStringList weights;
            for (double w : m_weights) weights << QString::number(w, 'f', 2);
            notes << QStringLiteral(
                         "auto chose %1 (%2) by cross-validation over the training runs (%3): "
                         "%4; the mean of the near-best %5 µm")
                         .arg(chosen(),
                              m_chosen.size() > 1
                                  ? QStringLiteral("stacked, weights %1: %2 µm cross-validated")
                                        .arg(weights.join(QStringLiteral(" + ")))
                                        .arg(choice.stack_rms_um, 0, 'g', 3)
                                  : QStringLiteral("stacked: the others take no weight"),
                              how, listed)
                         .arg(choice.mean_rms_um, 0, 'g', 3);
            break;
        }
    }
    if (!failed.isEmpty())
        notes << QStringLiteral("auto could not try: %1").arg(failed.join(QStringLiteral("; ")));
    summary.notes = notes + summary.notes;
    summary.message =
        choice.kind == CombinationChoice::Kind::None
            ? QStringLiteral("model 'auto' chose no compensation on %1 run(s)").arg(training.size())
            : QStringLiteral("model 'auto' chose '%1' and fitted it on %2 run(s)")
                  .arg(chosen())
                  .arg(training.size());
    return summary;
}

QString AutoModel::chosen() const {
    QStringList names;
    for (const auto& model : m_chosen) names << model->name();
    return names.join(QStringLiteral(" + "));
}

FitSummary AutoModel::combined(const std::vector<FitSummary>& fits) const {
    // Each family's figures under its own name: "arx/T_spindle.tau".
    FitSummary summary;
    for (std::size_t m = 0; m < fits.size(); ++m) {
        const QString family = m_chosen[m]->name();
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
    for (std::size_t m = 0; m < m_chosen.size(); ++m) {
        const Prediction p = m_chosen[m]->predict(run, at);
        if (!p.ok()) throw ModelError(p.error);
        sum += m_weights[m] * Eigen::Map<const Eigen::VectorXd>(p.error_um.data(),
                                                                Eigen::Index(p.error_um.size()));
    }
    return sum;
}

}  // namespace driftlab::models
