#pragma once
// heat-transfer: the screw simulation of docs/physics.md with its heat
// coefficients identified by Ceres from the temperatures on the screw and the
// positioning errors jointly. Physics generalises across moving states where
// regressions on temperatures do not: the headline of the cross-state matrix.
//
// The free parameters are data (a ScrewModelVariant), so the diagnosis can
// refit the same model extended by a candidate effect.

#include <functional>
#include <optional>

#include "core/models/ScrewRunSimulation.h"
#include "core/models/ThermalErrorModel.h"

namespace driftlab::models {

struct FreeParameter {
    QString name;  ///< as reported: "c_nut", "h", "h1", …
    QString unit;
    double initial = 0;
    double lower = 0;
    double upper = 0;
};

/// Which parameters are free and how they enter the simulation and its readings.
struct ScrewModelVariant {
    std::vector<FreeParameter> parameters;
    /// Sets the free values into the simulation's parameters.
    std::function<void(const double* values, physics::ScrewThermalParameters&)> physics;
    /// Optional: changes what drives the simulation before it runs (a late
    /// room sensor: the room the screw saw). On a copy, for each simulation.
    std::function<void(const double* values, ScrewRunInputs&)> inputs;
    /// Optional: changes the readings after the simulation (sensor or
    /// interferometer effects). Points are the thermal-error points of `out`.
    std::function<void(const double* values, const ScrewRunInputs&,
                       const std::vector<PredictionPoint>&, ScrewRunOutputs&)>
        readings;
};

/// c_nut, c_b, h; with `material` also ρc and k.
ScrewModelVariant baseScrewModel(bool material = false);

struct HeatTransferOptions {
    int cells = 100;  ///< identification grid (converged to < 0.1 µm, see the tests)
    double dt_s = 2;
    double temperature_sigma_K = 0.05;  ///< weights: the noise of each kind of reading
    double error_sigma_um = 0.5;
    double huber_sigmas = 3;  ///< residuals beyond this many σ count linearly (robust)
    int max_iterations = 50;
    /// Ceres stops when the cost changes by less than this share in a step …
    double function_tolerance = 1e-10;
    /// … or the parameters by less than this share.
    double parameter_tolerance = 1e-9;
    bool fit_temperatures = true;  ///< false: positioning errors only
    RoomInput room = RoomInput::Channel;
};

/// Measured − simulated, reading by reading, for one run.
struct ReadingResiduals {
    QString run_id;
    std::vector<PredictionPoint> points;  ///< the thermal-error observations
    std::vector<double> error_um;         ///< per point
    struct Sensor {
        QString channel_id;
        ChannelRole role = ChannelRole::Other;
        std::vector<double> time_s, residual_K;
    };
    std::vector<Sensor> sensors;
    /// Σ (r/σ)² over both kinds of reading with the model's nominal σ, and their count.
    double normalizedSquares = 0;
    std::size_t count = 0;
};

class HeatTransferModel : public ThermalErrorModel {
public:
    explicit HeatTransferModel(HeatTransferOptions options = {},
                               ScrewModelVariant variant = baseScrewModel());
    /// A model of the positioning error with `values` (in the variant's order)
    /// found elsewhere: the diagnosis fits an effect on the readings on the
    /// base simulation, then predicts with the whole extended model.
    HeatTransferModel(HeatTransferOptions options, ScrewModelVariant variant,
                      std::vector<double> values);

    QString name() const override { return QStringLiteral("heat-transfer"); }
    QString describe() const override;

    /// The fitted values, in the variant's order.
    const std::vector<double>& values() const { return m_values; }
    const ScrewModelVariant& variant() const { return m_variant; }
    /// What the fitted model misses on a run (throws ModelError on bad data).
    ReadingResiduals residuals(const RunData& run) const;
    const HeatTransferOptions& options() const { return m_options; }
    /// The screw of `run` with the fitted coefficients: what live compensation
    /// steps online. None (and why) before a fit or without a screw.
    std::optional<physics::ScrewThermalParameters> fittedScrew(const RunData& run,
                                                               QString* why) const;
    /// The run prepared for this model's step, room and grid.
    ScrewRunInputs prepared(const RunData& run) const;
    /// The simulation and the readings at `values` (any, fitted or not) for
    /// the prepared run `inputs`, at the points `at`.
    ScrewRunOutputs simulate(const double* values, const RunData& run, const ScrewRunInputs& inputs,
                             const std::vector<PredictionPoint>& at) const;
    /// Positioning errors, and the screw sensors' readings when they are fitted.
    std::size_t readingCount(const RunData& run, const ScrewRunInputs& inputs) const;
    /// The residuals the fit minimises (measured − `sim` at the run's
    /// observations, then each sensor's, over their nominal σ, Huber beyond
    /// `huberSigmas`) into `out`; returns how many.
    std::size_t normalisedResiduals(const ScrewRunOutputs& sim, const RunData& run,
                                    const ScrewRunInputs& inputs, double huberSigmas,
                                    double* out) const;

protected:
    FitSummary fitRuns(const std::vector<RunData>& training) override;
    Eigen::VectorXd predictRun(const RunData& run,
                               const std::vector<PredictionPoint>& at) const override;
    /// For a model that chooses its free parameters from the data (sensorless).
    void setVariant(ScrewModelVariant variant) { m_variant = std::move(variant); }
    /// What the fit minimises, ½Σ of the robust normalised residuals, at `values`.
    double cost(const std::vector<double>& values, const std::vector<RunData>& runs) const;

private:
    /// Writes the normalised residuals of one run (Huber at `huberSigmas`,
    /// none when infinite) to `out`; returns how many.
    std::size_t writeResiduals(const double* values, const RunData& run,
                               const ScrewRunInputs& inputs, double huberSigmas, double* out) const;
    physics::ScrewThermalParameters parametersWith(const double* values, const RunData& run) const;

    HeatTransferOptions m_options;
    ScrewModelVariant m_variant;
    std::vector<double> m_values;
};

}  // namespace driftlab::models
