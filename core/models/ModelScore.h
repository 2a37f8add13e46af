#pragma once
// Scoring models on held-out runs, and the cross-state matrix (fit on one
// moving state, score on every other): the headline comparison of docs/models.md.

#include <Eigen/Core>
#include <QString>
#include <QStringList>
#include <functional>
#include <limits>
#include <vector>

#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

struct Score {
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    double rms_um = kNaN;                ///< RMS of measured − predicted
    double peak_um = kNaN;               ///< largest |measured − predicted|
    double uncompensated_rms_um = kNaN;  ///< RMS of the measured thermal error itself
    /// 1 − rms_um/uncompensated_rms_um: the share of the thermal error the model
    /// removes (NaN when there is no thermal error to remove).
    double reduction = kNaN;
    std::size_t observations = 0;
    QString error;  ///< empty on success
    bool ok() const { return error.isEmpty(); }
};

/// Scores predictions against the measured thermal error.
Score scoreResiduals(const Eigen::VectorXd& measured_um, const Eigen::VectorXd& predicted_um);

/// Scores a fitted model on the test runs, their observations pooled.
Score scoreModel(const ThermalErrorModel& model, const std::vector<RunData>& test);

struct CrossStateMatrix {
    QStringList runs;
    /// rms_um[i][j]: RMS on run j of the model fitted on run i alone; NaN where
    /// the fit or the prediction failed (see errors).
    std::vector<std::vector<double>> rms_um;
    QStringList errors;  ///< one line per failed fit or prediction
    bool cancelled = false;
};

/// Fits model `modelName` on each run alone and scores it on every run.
/// `progress` gets the fraction done and may return false to cancel.
CrossStateMatrix crossStateMatrix(const QString& modelName, const std::vector<RunData>& runs,
                                  const std::function<bool(double fraction)>& progress = {});

}  // namespace driftlab::models
