#pragma once
// `arx`: the thermal error regressed on a few chosen temperature rises (no
// autoregressive terms, despite the id, which scripts keep using):
// each chosen sensor enters with its current rise and with its rise passed
// through a first-order lag whose time constant is fitted,
//   drift channel:     E(t)   = Σ_j [a_j·ΔT_j(t) + g_j·L_τj[ΔT_j](t)] (+ c)
//   positioning error: E(x,t) = Σ_j [ΔT_j·(a_j + b_j·dx) + L_τj[ΔT_j]·(g_j + h_j·dx)]
// with dx = x − x_fixed. A drift channel's fit gives each training run its own
// zero; a prediction takes none, or their mean c where cross-validation finds
// an offset the runs share (LaggedSensorsSearch.h). Drift that lags every sensor (the shaft and
// the column core carry no sensor) shows as hysteresis against the current temperatures; a lagged
// input follows it. The sensors and their time constants are chosen by cross-validation over the
// training runs (leave one run out; time blocks for a single run), as the ETH Zürich group's ARX
// pipeline selects its inputs.

#include <QStringList>
#include <vector>

#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

struct LaggedSensorsOptions {
    int max_sensors = 3;
    double min_tau_s = 60;
    double max_tau_s = 8 * 3600;
    int grid_points = 28;  ///< log-spaced time constants searched per sensor
    int time_blocks = 5;   ///< cross-validation blocks of a single training run
    /// Observations per run used to choose sensors and time constants (evenly
    /// thinned: 5 s samples over hours add time, not information); the gains
    /// are then fitted on every observation.
    int search_rows_per_run = 400;
};

class LaggedSensorsModel final : public ThermalErrorModel {
public:
    explicit LaggedSensorsModel(LaggedSensorsOptions options = {});
    QString name() const override { return QStringLiteral("arx"); }
    QString describe() const override;

protected:
    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;

private:
    /// One chosen input: a sensor and the time constant of its lagged rise.
    struct Input {
        QString channel;
        double tau_s = 0;
    };
    /// [ΔT_j, L_τj[ΔT_j]] of every chosen input at the points.
    Eigen::MatrixXd features(const RunData& run, const std::vector<PredictionPoint>& at) const;

    LaggedSensorsOptions m_options;
    std::vector<Input> m_inputs;
    Eigen::VectorXd m_coefficients;
    /// A drift channel's offset at prediction: the training runs' mean zero,
    /// where cross-validation preferred it to none (µm).
    double m_commonZero_um = 0;
};

}  // namespace driftlab::models
