#include "core/models/ModelScore.h"

#include <cmath>

#include "core/models/ModelFactory.h"

namespace driftlab::models {
namespace {

Score failed(const QString& error) {
    Score s;
    s.error = error;
    return s;
}

double rms(const Eigen::VectorXd& v) {
    return std::sqrt(v.squaredNorm() / double(v.size()));
}

}  // namespace

Score scoreResiduals(const Eigen::VectorXd& measured_um, const Eigen::VectorXd& predicted_um) {
    if (measured_um.size() != predicted_um.size())
        return failed(QStringLiteral("%1 measurements but %2 predictions")
                          .arg(measured_um.size())
                          .arg(predicted_um.size()));
    if (measured_um.size() == 0) return failed(QStringLiteral("no observations to score"));
    const Eigen::VectorXd residual = measured_um - predicted_um;
    Score s;
    s.rms_um = rms(residual);
    s.peak_um = residual.cwiseAbs().maxCoeff();
    s.uncompensated_rms_um = rms(measured_um);
    if (s.uncompensated_rms_um > 0) s.reduction = 1 - s.rms_um / s.uncompensated_rms_um;
    s.observations = std::size_t(measured_um.size());
    return s;
}

Score scoreModel(const ThermalErrorModel& model, const std::vector<RunData>& test) {
    std::vector<double> measured, predicted;
    for (const RunData& run : test) {
        const Prediction p = model.predict(run);
        if (!p.ok()) return failed(p.error);
        for (const ErrorObservation& o : run.observations) measured.push_back(o.error_um);
        predicted.insert(predicted.end(), p.error_um.begin(), p.error_um.end());
    }
    return scoreResiduals(
        Eigen::Map<const Eigen::VectorXd>(measured.data(), Eigen::Index(measured.size())),
        Eigen::Map<const Eigen::VectorXd>(predicted.data(), Eigen::Index(predicted.size())));
}

CrossStateMatrix crossStateMatrix(const QString& modelName, const std::vector<RunData>& runs,
                                  const std::function<bool(double fraction)>& progress) {
    CrossStateMatrix matrix;
    for (const RunData& run : runs) matrix.runs << run.run_id;
    matrix.rms_um.assign(runs.size(), std::vector<double>(runs.size(), Score::kNaN));
    if (!makeModel(modelName)) {
        matrix.errors << QStringLiteral("unknown model '%1' (known: %2)")
                             .arg(modelName, modelNames().join(QStringLiteral(", ")));
        return matrix;
    }
    // Asked between runs and, through the model's cancel check, inside a long fit.
    double done = 0;
    bool stopped = false;
    const auto cancelled = [&] { return stopped = stopped || (progress && !progress(done)); };
    for (std::size_t i = 0; i < runs.size(); ++i) {
        done = double(i) / double(runs.size());
        if (cancelled()) {
            matrix.cancelled = true;
            return matrix;
        }
        const std::unique_ptr<ThermalErrorModel> model = makeModel(modelName);
        model->setCancelCheck(cancelled);
        const FitSummary fit = model->fit({runs[i]});
        if (stopped) {
            matrix.cancelled = true;
            return matrix;
        }
        if (!fit.success) {
            matrix.errors << QStringLiteral("fit on run '%1': %2").arg(runs[i].run_id, fit.message);
            continue;
        }
        for (std::size_t j = 0; j < runs.size(); ++j) {
            const Score score = scoreModel(*model, {runs[j]});
            if (score.ok())
                matrix.rms_um[i][j] = score.rms_um;
            else
                matrix.errors << QStringLiteral("fitted on run '%1', scored on run '%2': %3")
                                     .arg(runs[i].run_id, runs[j].run_id, score.error);
        }
    }
    if (progress) progress(1.0);
    return matrix;
}

}  // namespace driftlab::models
