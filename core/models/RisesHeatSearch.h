#pragma once
// What the shrunken all-rises families (`lsall-heat`, `ridge-heat`,
// `pcr-heat`) share: a spindle's drift channel read through every temperature
// rise, and the spindle's heat — its speed n in 1000 rpm to the power p = 1
// or 2 — through a first-order lag L_τ[n^p], with one offset common to all
// runs. The candidates (no heat, or p and τ from `arx-all`'s heat grid) are
// scored by cross-validation over the training runs on a thinned set of rows
// (leave one run out; time blocks for a single run), each candidate's column
// computed once.

#include <Eigen/Core>
#include <QString>
#include <QStringList>
#include <vector>

#include "core/models/FirstOrderLag.h"
#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

struct RisesHeatOptions {
    double min_tau_s = 60;
    double max_tau_s = 8 * 3600;
    double tau_step = 1.5;  ///< ratio of neighbouring time constants searched
    int time_blocks = 5;    ///< cross-validation blocks of a single training run
    /// Observations per run the search scores on (evenly thinned); the final
    /// fit takes every observation.
    int search_rows_per_run = 400;
    /// The heat's lag is searched up to this fraction of the shortest
    /// training run (as `arx-all`'s: a longer one acts as a ramp).
    double max_heat_tau_of_run = 0.25;
};

/// The spindle's heat through a lag, L_τ[n^p]; exponent 0: none.
struct SpindleHeat {
    int exponent = 0;
    double tau_s = 0;
    bool none() const { return exponent == 0; }
    /// "the spindle's speed² through a lag of 25 min", for notes.
    QString describe() const;
    /// "speed" or "speed²", the parameters' prefix.
    QString key() const;
    /// "krpm" or "krpm²".
    QString unit() const;
};

/// The run with every k-th observation, about `rows` of them: 5 s samples
/// over hours add time to a search, not information.
RunData thinnedRun(const RunData& run, int rows);

/// The spindle's speed in 1000 rpm raised to `exponent`, as a lag input;
/// throws ModelError naming `model` when the run has no speed channel.
PiecewiseInput spindleHeatInput(const RunData& run, int exponent, const QString& model);

/// L_τ[n^p] at the points: one column, or none for no heat.
Eigen::MatrixXd spindleHeatAt(const RunData& run, const SpindleHeat& heat,
                              const std::vector<PredictionPoint>& at, const QString& model);

/// [features, heat, 1]: a design with one offset common to all runs.
Eigen::MatrixXd withHeatAndOffset(const Eigen::MatrixXd& features, const Eigen::MatrixXd& heat);

class RisesHeatSearch {
public:
    /// Reads the usable temperature channels (notes in `summary` for those
    /// left out) and builds every heat candidate's column. Throws ModelError
    /// naming `model` for a positioning error: these families model a
    /// spindle's drift, whose heat is the spindle speed.
    RisesHeatSearch(const std::vector<RunData>& training, const QString& model,
                    const RisesHeatOptions& options, FitSummary& summary);

    const QStringList& channels() const { return m_channels; }
    /// The search rows' rises (rows × channels), errors and folds.
    const Eigen::MatrixXd& rises() const { return m_rises; }
    const Eigen::VectorXd& observed() const { return m_observed; }
    const std::vector<int>& folds() const { return m_folds; }
    /// No heat first, then each (p, τ) the training runs allow.
    const std::vector<SpindleHeat>& heats() const { return m_heats; }
    /// The candidate's column over the search rows (no column for no heat).
    const Eigen::MatrixXd& heatColumn(std::size_t candidate) const { return m_columns[candidate]; }
    /// Why no heat is tried (one run, no speed channel), or empty.
    const QString& heatNote() const { return m_heatNote; }

private:
    QStringList m_channels;
    Eigen::MatrixXd m_rises;
    Eigen::VectorXd m_observed;
    std::vector<int> m_folds;
    std::vector<SpindleHeat> m_heats;
    std::vector<Eigen::MatrixXd> m_columns;
    QString m_heatNote;
};

/// Puts `c` and, for a heat, its gain and τ into the summary from the fitted
/// coefficients (the heat's at `heatColumn`, the offset last).
void reportHeatAndOffset(FitSummary& summary, const Eigen::VectorXd& coefficients,
                         const Eigen::VectorXd& sigma, const SpindleHeat& heat,
                         Eigen::Index heatColumn);

}  // namespace driftlab::models
