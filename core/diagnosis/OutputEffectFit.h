#pragma once
// Fitting an effect on the readings (a sensor's offset or lag, refraction,
// frame growth) without a new screw simulation. What the screw does depends on
// the heat parameters only, so the step's simulation is run once per training
// run with its fitted values, and once more per heat parameter a little off
// them: the readings then follow the heat parameters along those
// sensitivities (exactly in the heat inputs c_nut and c_b, to which the heat
// equation is linear; to first order in h and the like), while the effect's
// own parameters act on the readings exactly. The effect is fitted jointly
// with the heat parameters freed, as a full identification would, for the
// cost of a few simulations shared by every such candidate; a fit that moves
// a nonlinear parameter far is linearised again where it landed.

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/diagnosis/CandidateEffects.h"
#include "core/models/HeatTransferModel.h"

namespace driftlab::diagnosis {

/// A candidate's extension fitted on its training runs.
struct FittedExtension {
    std::shared_ptr<const models::HeatTransferModel> model;
    models::FitSummary fit;
};

class StepSimulation {
public:
    /// The simulation of `model` (the base model extended by `effects`, fitted)
    /// on `train`; throws ModelError on bad data.
    StepSimulation(std::shared_ptr<const models::HeatTransferModel> model,
                   std::vector<CandidateEffect> effects, const std::vector<models::RunData>& train);

    /// `candidate` (output_only) fitted on top of the step's effects from
    /// `ownStart` (its own parameters' starting values; empty: their
    /// defaults); nullopt when the fit fails or `cancelled` says so.
    std::optional<FittedExtension> fit(const CandidateEffect& candidate,
                                       const std::vector<double>& ownStart,
                                       const std::function<bool()>& cancelled) const;

private:
    /// The step's simulation and its sensitivities at `at` (the heat
    /// parameters' values), run by run.
    struct Linearised {
        std::vector<double> at;
        std::vector<models::ScrewRunOutputs> base;                ///< per run
        std::vector<std::vector<models::ScrewRunOutputs>> slope;  ///< per run, per parameter
    };
    Linearised linearise(std::vector<double> at) const;
    /// The heat parameters' values among all of a variant's (`m_simulated`).
    std::vector<double> simulatedOf(const std::vector<double>& values) const;

    std::shared_ptr<const models::HeatTransferModel> m_model;
    std::vector<CandidateEffect> m_effects;
    const std::vector<models::RunData>& m_train;
    /// The step's model without its effects on the readings: what the
    /// simulation computes, of the parameters `m_simulated` of the step's.
    models::HeatTransferModel m_simulation;
    std::vector<std::size_t> m_simulated;
    std::vector<models::ScrewRunInputs> m_inputs;  ///< per training run, prepared once
    Linearised m_linearised;
};

}  // namespace driftlab::diagnosis
