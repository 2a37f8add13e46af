#pragma once
// The interface every thermal-error model implements: fit on training runs,
// predict the thermal error of any run of the same campaign. Bad data never
// throws across this interface; it gives success = false and a message that
// names the run, channel or role at fault.

#include <Eigen/Core>
#include <QString>
#include <QStringList>
#include <functional>
#include <limits>
#include <map>
#include <vector>

#include "core/models/ThermalErrorData.h"

namespace driftlab::models {

struct Parameter {
    double value = 0;
    /// 1σ uncertainty; NaN when the data do not determine it.
    double sigma = std::numeric_limits<double>::quiet_NaN();
    QString unit;
};

struct FitSummary {
    bool success = false;
    QString message;  ///< why the fit failed, or what was fitted
    std::map<QString, Parameter> parameters;
    /// Model-specific figures, e.g. "cv_rms_um", "degree", "best_single_r2".
    std::map<QString, double> metrics;
    QStringList inputs;  ///< the channels and signals the fitted model reads
    QStringList notes;   ///< what the user should know, e.g. a channel left out and why
    double rms_um = std::numeric_limits<double>::quiet_NaN();  ///< RMS of the training residual
    std::size_t observations = 0;                              ///< training observations
    int iterations = 0;  ///< of the nonlinear search; 0 for linear models
};

struct Prediction {
    std::vector<double> error_um;
    QString error;  ///< empty on success
    bool ok() const { return error.isEmpty(); }
};

class ThermalErrorModel {
public:
    virtual ~ThermalErrorModel() = default;

    /// The factory name ("mlr", "poly-position", ...).
    virtual QString name() const = 0;
    /// One sentence for a test engineer: what the model assumes.
    virtual QString describe() const = 0;

    /// Fits on the training runs, all from one buildDataset call (same target).
    FitSummary fit(const std::vector<RunData>& training);
    bool isFitted() const { return m_fitted; }
    /// Asked during a long fit (between solver iterations and search steps):
    /// true stops it, and fit() then fails with "… fit cancelled". The GUI's
    /// Cancel sets an atomic flag this reads; it is called on the fitting thread.
    void setCancelCheck(std::function<bool()> cancelled) { m_cancelled = std::move(cancelled); }
    bool cancelRequested() const { return m_cancelled && m_cancelled(); }

    /// The thermal error at the run's observation points.
    Prediction predict(const RunData& run) const;
    /// The thermal error at any times and positions, from the run's own
    /// temperatures and signals.
    Prediction predict(const RunData& run, const std::vector<PredictionPoint>& at) const;

protected:
    /// Fits parameters, metrics, inputs and notes; rms_um, observations and
    /// success are filled in by fit(). Throws ModelError on bad data.
    virtual FitSummary fitRuns(const std::vector<RunData>& training) = 0;
    /// One value per point. Throws ModelError on bad data.
    virtual Eigen::VectorXd predictRun(const RunData& run,
                                       const std::vector<PredictionPoint>& at) const = 0;
    /// For a model whose values were found outside fit() (the diagnosis's
    /// fits of an effect on the readings): it predicts `targetChannel` from now on.
    void markFitted(const QString& targetChannel) {
        m_fitted = true;
        m_target_channel = targetChannel;
    }

private:
    /// predictRun, checked for a value per point and finiteness.
    Eigen::VectorXd checkedPrediction(const RunData& run,
                                      const std::vector<PredictionPoint>& at) const;

    bool m_fitted = false;
    QString m_target_channel;
    std::function<bool()> m_cancelled;
};

}  // namespace driftlab::models
