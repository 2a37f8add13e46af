#include "core/diagnosis/OutputEffectFit.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <cmath>

#include "core/models/CeresResiduals.h"
#include "core/models/ModelError.h"

namespace driftlab::diagnosis {
namespace {

using models::ScrewRunInputs;
using models::ScrewRunOutputs;

/// Where each effect's parameters start in a variant of the base and `effects`.
std::vector<std::size_t> offsetsOf(const std::vector<CandidateEffect>& effects) {
    std::vector<std::size_t> offsets;
    std::size_t at = models::baseScrewModel().parameters.size();
    for (const CandidateEffect& e : effects) {
        offsets.push_back(at);
        at += e.parameters.size();
    }
    return offsets;
}

/// `a` + f·`b`, reading by reading.
void addScaled(ScrewRunOutputs& a, const ScrewRunOutputs& b, double f) {
    for (std::size_t i = 0; i < a.error_um.size(); ++i) a.error_um[i] += f * b.error_um[i];
    for (std::size_t s = 0; s < a.sensor_C.size(); ++s)
        for (std::size_t j = 0; j < a.sensor_C[s].size(); ++j)
            a.sensor_C[s][j] += f * b.sensor_C[s][j];
}

/// A nonlinear parameter moved this far from where the simulation was
/// linearised (as a share of its value, at least of a thousandth of its
/// range) is linearised again.
constexpr double kRelinearise = 0.05;
constexpr int kMaxLinearisations = 3;

double scaleOf(const models::FreeParameter& p, double value) {
    return std::max(std::abs(value), 1e-3 * (p.upper - p.lower));
}

}  // namespace

StepSimulation::StepSimulation(std::shared_ptr<const models::HeatTransferModel> model,
                               std::vector<CandidateEffect> effects,
                               const std::vector<models::RunData>& train)
    : m_model(std::move(model)),
      m_effects(std::move(effects)),
      m_train(train),
      m_simulation(m_model->options(), [&] {
          std::vector<CandidateEffect> simulated;
          for (const CandidateEffect& e : m_effects)
              if (!e.output_only) simulated.push_back(e);
          return extendedModel(simulated, {});
      }()) {
    // The heat parameters: the base model's, and those of the effects that
    // change the simulation.
    const std::vector<std::size_t> offsets = offsetsOf(m_effects);
    for (std::size_t i = 0; i < models::baseScrewModel().parameters.size(); ++i)
        m_simulated.push_back(i);
    for (std::size_t e = 0; e < m_effects.size(); ++e)
        if (!m_effects[e].output_only)
            for (std::size_t k = 0; k < m_effects[e].parameters.size(); ++k)
                m_simulated.push_back(offsets[e] + k);
    for (const models::RunData& run : m_train) m_inputs.push_back(m_simulation.prepared(run));
    m_linearised = linearise(simulatedOf(m_model->values()));
}

std::vector<double> StepSimulation::simulatedOf(const std::vector<double>& values) const {
    std::vector<double> at;
    for (std::size_t i : m_simulated) at.push_back(values[i]);
    return at;
}

StepSimulation::Linearised StepSimulation::linearise(std::vector<double> at) const {
    Linearised l;
    l.at = std::move(at);
    const auto& free = m_simulation.variant().parameters;
    for (std::size_t r = 0; r < m_train.size(); ++r) {
        const auto points = m_train[r].observationPoints();
        l.base.push_back(m_simulation.simulate(l.at.data(), m_train[r], m_inputs[r], points));
        std::vector<ScrewRunOutputs> slopes;
        for (std::size_t j = 0; j < l.at.size(); ++j) {
            std::vector<double> moved = l.at;
            double step = 1e-3 * scaleOf(free[j], l.at[j]);
            if (moved[j] + step > free[j].upper) step = -step;
            moved[j] += step;
            ScrewRunOutputs slope =
                m_simulation.simulate(moved.data(), m_train[r], m_inputs[r], points);
            addScaled(slope, l.base.back(), -1);
            for (double& e : slope.error_um) e /= step;
            for (auto& s : slope.sensor_C)
                for (double& t : s) t /= step;
            slopes.push_back(std::move(slope));
        }
        l.slope.push_back(std::move(slopes));
    }
    return l;
}

std::optional<FittedExtension> StepSimulation::fit(const CandidateEffect& candidate,
                                                   const std::vector<double>& ownStart,
                                                   const std::function<bool()>& cancelled) const {
    std::vector<CandidateEffect> effects = m_effects;
    effects.push_back(candidate);
    const std::vector<std::size_t> offsets = offsetsOf(effects);
    std::vector<double> start = m_model->values();
    start.insert(start.end(), ownStart.begin(), ownStart.end());
    const models::ScrewModelVariant variant = extendedModel(effects, start);
    const auto& free = variant.parameters;
    const int n = int(free.size());
    std::vector<double> values;
    for (const auto& p : free) values.push_back(p.initial);

    const models::HeatTransferOptions& options = m_model->options();
    int residualCount = 0;
    for (std::size_t r = 0; r < m_train.size(); ++r)
        residualCount += int(m_model->readingCount(m_train[r], m_inputs[r]));
    bool changesInputs = false;
    for (const CandidateEffect& e : effects)
        changesInputs = changesInputs || (e.output_only && e.inputs);

    Linearised l = m_linearised;
    auto evaluate = [&](const double* p, double* residuals) {
        for (std::size_t r = 0; r < m_train.size(); ++r) {
            ScrewRunOutputs out = l.base[r];
            for (std::size_t j = 0; j < m_simulated.size(); ++j)
                addScaled(out, l.slope[r][j], p[m_simulated[j]] - l.at[j]);
            std::optional<ScrewRunInputs> changed;
            if (changesInputs) {
                changed.emplace(m_inputs[r]);
                for (std::size_t e = 0; e < effects.size(); ++e)
                    if (effects[e].output_only && effects[e].inputs)
                        effects[e].inputs(p + offsets[e], *changed);
            }
            const ScrewRunInputs& in = changed ? *changed : m_inputs[r];
            const auto points = m_train[r].observationPoints();
            for (std::size_t e = 0; e < effects.size(); ++e)
                if (effects[e].output_only && effects[e].readings)
                    effects[e].readings(p + offsets[e], in, points, out);
            residuals +=
                m_model->normalisedResiduals(out, m_train[r], in, options.huber_sigmas, residuals);
        }
        return true;
    };

    ceres::Solver::Summary solved;
    int iterations = 0;
    for (int round = 0; round < kMaxLinearisations; ++round) {
        ceres::Problem problem;
        problem.AddResidualBlock(models::numericCost<ceres::FORWARD>(evaluate, n, residualCount),
                                 nullptr, values.data());
        for (int i = 0; i < n; ++i) {
            problem.SetParameterLowerBound(values.data(), i, free[std::size_t(i)].lower);
            problem.SetParameterUpperBound(values.data(), i, free[std::size_t(i)].upper);
        }
        ceres::Solver::Options solverOptions;
        solverOptions.linear_solver_type = ceres::DENSE_QR;
        solverOptions.max_num_iterations = options.max_iterations;
        solverOptions.function_tolerance = options.function_tolerance;
        solverOptions.parameter_tolerance = options.parameter_tolerance;
        solverOptions.logging_type = ceres::SILENT;
        models::CancelCallback cancel(cancelled);
        solverOptions.callbacks.push_back(&cancel);
        ceres::Solve(solverOptions, &problem, &solved);
        iterations += int(solved.iterations.size());
        if ((cancelled && cancelled()) || !solved.IsSolutionUsable()) return std::nullopt;
        bool far = false;
        for (std::size_t j = 0; j < m_simulated.size(); ++j)
            far = far || std::abs(values[m_simulated[j]] - l.at[j]) >
                             kRelinearise * scaleOf(free[m_simulated[j]], l.at[j]);
        if (!far || round + 1 == kMaxLinearisations) {
            // 1σ from the Jacobian at the solution, scaled by the residual
            // variance, as the identification reports it.
            ceres::CRSMatrix crs;
            problem.Evaluate(ceres::Problem::EvaluateOptions(), nullptr, nullptr, nullptr, &crs);
            Eigen::MatrixXd J = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
            for (int row = 0; row < crs.num_rows; ++row)
                for (int k = crs.rows[std::size_t(row)]; k < crs.rows[std::size_t(row) + 1]; ++k)
                    J(row, crs.cols[std::size_t(k)]) = crs.values[std::size_t(k)];
            const Eigen::MatrixXd information = J.transpose() * J;
            const Eigen::FullPivLU<Eigen::MatrixXd> lu(information);
            const double variance = 2 * solved.final_cost / std::max(1, residualCount - n);
            FittedExtension fitted;
            fitted.fit.success = true;
            fitted.fit.iterations = iterations;
            fitted.fit.metrics[QStringLiteral("final_cost")] = solved.final_cost;
            fitted.fit.metrics[QStringLiteral("linearisations")] = round + 1;
            const Eigen::MatrixXd covariance =
                lu.isInvertible() ? Eigen::MatrixXd(lu.inverse() * variance) : Eigen::MatrixXd();
            for (int i = 0; i < n; ++i) {
                const auto& p = free[std::size_t(i)];
                const double sigma = covariance.size() > 0
                                         ? std::sqrt(std::max(0.0, covariance(i, i)))
                                         : std::nan("");
                fitted.fit.parameters[p.name] = {values[std::size_t(i)], sigma, p.unit};
            }
            fitted.fit.message = QStringLiteral(
                                     "%1 fitted on the step's simulation, its heat parameters "
                                     "freed along their sensitivities (%2 iterations)")
                                     .arg(candidate.cause)
                                     .arg(iterations);
            fitted.model = std::make_shared<models::HeatTransferModel>(
                options, extendedModel(effects, values), values);
            return fitted;
        }
        l = linearise(simulatedOf(values));
    }
    return std::nullopt;
}

}  // namespace driftlab::diagnosis
