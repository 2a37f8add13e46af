#pragma once
// `arx-all`: least squares on every temperature rise, plus one rise through a
// first-order lag,
//   drift channel:     E(t)   = Σ_k a_k·ΔT_k(t) + g·L_τ[ΔT_j](t) + c
//   positioning error: E(x,t) = Σ_k ΔT_k·(a_k + b_k·dx) + L_τ[ΔT_j]·(g + h·dx)
// with dx = x − x_fixed, the lagged sensor j and τ chosen by cross-validation
// over the training runs (or none). Where many thermometers sit around the
// heat paths, the parts that move the tool but carry no sensor are, but for
// one, nearly a weighted sum of their neighbours: all the rises give them
// statically, where `mlr` and `arx` take three sensors at most; the part that
// lags them all (a spindle shaft behind its bearings and stator, a column core
// behind its skin) takes the lag.

#include <QStringList>
#include <vector>

#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

struct AllRisesLagOptions {
    double min_tau_s = 60;
    double max_tau_s = 8 * 3600;
    double tau_step = 1.5;  ///< ratio of neighbouring time constants searched
    int time_blocks = 5;    ///< cross-validation blocks of a single training run
    /// Observations per run the search scores on (evenly thinned, as `arx`'s);
    /// the gains are then fitted on every observation.
    int search_rows_per_run = 400;
};

class AllRisesLagModel final : public ThermalErrorModel {
public:
    explicit AllRisesLagModel(AllRisesLagOptions options = {});
    QString name() const override { return QStringLiteral("arx-all"); }
    QString describe() const override;

protected:
    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;

private:
    /// [every rise, the lagged rise (if any), 1] at the points, with the
    /// position-gain copies for a positioning error.
    Eigen::MatrixXd design(const RunData& run, const std::vector<PredictionPoint>& at, int lagged,
                           double tau_s) const;

    AllRisesLagOptions options_;
    QStringList channels_;
    int lagged_ = -1;  ///< index in channels_; −1: no lagged rise
    double tau_s_ = 0;
    Eigen::VectorXd coefficients_;
};

}  // namespace driftlab::models
