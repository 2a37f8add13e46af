#include "core/models/ThermalErrorModel.h"

#include <cmath>

#include "core/models/ModelError.h"

namespace driftlab::models {
namespace {

QString targetName(const QString& targetChannel) {
    return targetChannel.isEmpty() ? QStringLiteral("the positioning error")
                                   : QStringLiteral("channel '%1'").arg(targetChannel);
}

}  // namespace

FitSummary ThermalErrorModel::fit(const std::vector<RunData>& training) {
    m_fitted = false;
    try {
        if (training.empty())
            throw ModelError(
                QStringLiteral("model '%1' needs at least one training run").arg(name()));
        for (const RunData& run : training)
            if (run.target_channel != training.front().target_channel)
                throw ModelError(QStringLiteral("training runs '%1' and '%2' have different "
                                                "targets (%3, %4)")
                                     .arg(training.front().run_id, run.run_id,
                                          targetName(training.front().target_channel),
                                          targetName(run.target_channel)));
        FitSummary summary = fitRuns(training);
        // A model that does not look at the flag itself is stopped here at
        // the latest, so a cancelled fit never counts as a result.
        if (cancelRequested())
            throw ModelError(QStringLiteral("model '%1': fit cancelled").arg(name()));
        m_target_channel = training.front().target_channel;
        m_fitted = true;
        double squares = 0;
        for (const RunData& run : training) {
            squares += (run.observedErrors() - checkedPrediction(run, run.observationPoints()))
                           .squaredNorm();
            summary.observations += run.observations.size();
        }
        summary.rms_um = std::sqrt(squares / double(summary.observations));
        summary.success = true;
        if (summary.message.isEmpty())
            summary.message = QStringLiteral("model '%1' fitted on %2 run(s), %3 observations")
                                  .arg(name())
                                  .arg(training.size())
                                  .arg(summary.observations);
        return summary;
    } catch (const ModelError& e) {
        m_fitted = false;
        FitSummary failed;
        failed.message = e.message;
        return failed;
    }
}

Prediction ThermalErrorModel::predict(const RunData& run) const {
    return predict(run, run.observationPoints());
}

Prediction ThermalErrorModel::predict(const RunData& run,
                                      const std::vector<PredictionPoint>& at) const {
    Prediction prediction;
    try {
        if (!m_fitted) throw ModelError(QStringLiteral("model '%1' is not fitted").arg(name()));
        if (run.target_channel != m_target_channel)
            throw ModelError(QStringLiteral("model '%1' was fitted to %2; run '%3' asks for %4")
                                 .arg(name(), targetName(m_target_channel), run.run_id,
                                      targetName(run.target_channel)));
        const Eigen::VectorXd e = checkedPrediction(run, at);
        prediction.error_um.assign(e.data(), e.data() + e.size());
    } catch (const ModelError& e) {
        prediction.error = e.message;
    }
    return prediction;
}

Eigen::VectorXd ThermalErrorModel::checkedPrediction(const RunData& run,
                                                     const std::vector<PredictionPoint>& at) const {
    const Eigen::VectorXd e = predictRun(run, at);
    if (e.size() != Eigen::Index(at.size()) || !e.allFinite())
        throw ModelError(QStringLiteral("model '%1' gave no finite prediction for run '%2'")
                             .arg(name(), run.run_id));
    return e;
}

}  // namespace driftlab::models
