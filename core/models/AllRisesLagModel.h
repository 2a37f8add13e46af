#pragma once
// `arx-all`: least squares on every temperature rise, plus one rise and, for
// a drift channel, the spindle's heat through first-order lags,
//   drift channel:     E(t)   = Σ_k a_k·ΔT_k(t) + g·L_τ[ΔT_j](t) + q·L_τq[n^p](t) + c
//   positioning error: E(x,t) = Σ_k ΔT_k·(a_k + b_k·dx) + L_τ[ΔT_j]·(g + h·dx)
// with dx = x − x_fixed, n the spindle's speed in 1000 rpm, p = 1 or 2; the
// lagged sensor j and τ, then p and τq (from two training runs on), chosen by
// cross-validation over the training runs (or none); a drift channel's zero
// fitted per training run, as for `arx`. Where many thermometers sit around
// the heat paths, the parts that move the tool but carry no sensor are, but
// for one, nearly a weighted sum of their neighbours: all the rises give them
// statically, where `mlr` and `arx` take three sensors at most; the part that
// lags them all (a spindle shaft behind its bearings and stator, a column core
// behind its skin) takes the lag. A part heated by its own losses (the rotor
// and shaft) follows its heat source as much as its neighbours: the lagged
// speed gives that heat.

#include <QStringList>
#include <vector>

#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

struct LeastSquaresFit;

struct AllRisesLagOptions {
    double min_tau_s = 60;
    double max_tau_s = 8 * 3600;
    double tau_step = 1.5;  ///< ratio of neighbouring time constants searched
    int time_blocks = 5;    ///< cross-validation blocks of a single training run
    /// Observations per run the search scores on (evenly thinned, as `arx`'s);
    /// the gains are then fitted on every observation.
    int search_rows_per_run = 400;
    /// The heat input's lag is searched up to this fraction of the shortest
    /// training run: a longer one does not settle within the runs, which then
    /// cannot tell it from a ramp of the energy put in.
    double max_heat_tau_of_run = 0.25;
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
    /// [every rise, the lagged rise and the lagged heat (those chosen), 1] at
    /// the points, with the position-gain copies for a positioning error.
    Eigen::MatrixXd design(const RunData& run, const std::vector<PredictionPoint>& at) const;
    /// The gains per position (every rise, then the lags chosen).
    Eigen::Index features() const {
        return Eigen::Index(m_channels.size()) + (m_lagged >= 0 ? 1 : 0) +
               (m_heatExponent > 0 ? 1 : 0);
    }
    /// Puts every fitted gain and time constant into the summary; returns the
    /// lags chosen, described for the note.
    QStringList reportGains(FitSummary& summary, const LeastSquaresFit& fit,
                            bool positionDependent) const;

    AllRisesLagOptions m_options;
    QStringList m_channels;
    int m_lagged = -1;  ///< index in m_channels; −1: no lagged rise
    double m_tau_s = 0;
    int m_heatExponent = 0;  ///< of the spindle's speed; 0: no lagged heat input
    double m_heatTau_s = 0;
    Eigen::VectorXd m_coefficients;  ///< the gains; a drift channel's run zeros apart
    double m_offset_um = 0;          ///< a drift channel's predicted offset
};

}  // namespace driftlab::models
