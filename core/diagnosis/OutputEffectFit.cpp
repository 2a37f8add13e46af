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
    : model_(std::move(model)),
      effects_(std::move(effects)),
      train_(train),
      simulation_(model_->options(), [&] {
          std::vector<CandidateEffect> simulated;
          for (const CandidateEffect& e : effects_)
              if (!e.output_only) simulated.push_back(e);
          return extendedModel(simulated, {});
      }()) {
    // The heat parameters: the base model's, and those of the effects that
    // change the simulation.
    const std::vector<std::size_t> offsets = offsetsOf(effects_);
    for (std::size_t i = 0; i < models::baseScrewModel().parameters.size(); ++i)
        simulated_.push_back(i);
    for (std::size_t e = 0; e < effects_.size(); ++e)
        if (!effects_[e].output_only)
            for (std::size_t k = 0; k < effects_[e].parameters.size(); ++k)
                simulated_.push_back(offsets[e] + k);
    for (const models::RunData& run : train_) inputs_.push_back(simulation_.prepared(run));
    linearised_ = linearise(simulatedOf(model_->values()));
}

std::vector<double> StepSimulation::simulatedOf(const std::vector<double>& values) const {
    std::vector<double> at;
    for (std::size_t i : simulated_) at.push_back(values[i]);
    return at;
}

StepSimulation::Linearised StepSimulation::linearise(std::vector<double> at) const {
    Linearised l;
    l.at = std::move(at);
    const auto& free = simulation_.variant().parameters;
    for (std::size_t r = 0; r < train_.size(); ++r) {
        const auto points = train_[r].observationPoints();
        l.base.push_back(simulation_.simulate(l.at.data(), train_[r], inputs_[r], points));
        std::vector<ScrewRunOutputs> slopes;
        for (std::size_t j = 0; j < l.at.size(); ++j) {
            std::vector<double> moved = l.at;
            double step = 1e-3 * scaleOf(free[j], l.at[j]);
            if (moved[j] + step > free[j].upper) step = -step;
            moved[j] += step;
            ScrewRunOutputs slope =
                simulation_.simulate(moved.data(), train_[r], inputs_[r], points);
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
    std::vector<CandidateEffect> effects = effects_;
    effects.push_back(candidate);
    const std::vector<std::size_t> offsets = offsetsOf(effects);
    std::vector<double> start = model_->values();
    start.insert(start.end(), ownStart.begin(), ownStart.end());
    const models::ScrewModelVariant variant = extendedModel(effects, start);
    const auto& free = variant.parameters;
    const int n = int(free.size());
    std::vector<double> values;
    for (const auto& p : free) values.push_back(p.initial);

    const models::HeatTransferOptions& options = model_->options();
    int residualCount = 0;
    for (std::size_t r = 0; r < train_.size(); ++r)
        residualCount += int(model_->readingCount(train_[r], inputs_[r]));
    bool changesInputs = false;
    for (const CandidateEffect& e : effects)
        changesInputs = changesInputs || (e.output_only && e.inputs);

    Linearised l = linearised_;
    auto evaluate = [&](const double* p, double* residuals) {
        for (std::size_t r = 0; r < train_.size(); ++r) {
            ScrewRunOutputs out = l.base[r];
            for (std::size_t j = 0; j < simulated_.size(); ++j)
                addScaled(out, l.slope[r][j], p[simulated_[j]] - l.at[j]);
            std::optional<ScrewRunInputs> changed;
            if (changesInputs) {
                changed.emplace(inputs_[r]);
                for (std::size_t e = 0; e < effects.size(); ++e)
                    if (effects[e].output_only && effects[e].inputs)
                        effects[e].inputs(p + offsets[e], *changed);
            }
            const ScrewRunInputs& in = changed ? *changed : inputs_[r];
            const auto points = train_[r].observationPoints();
            for (std::size_t e = 0; e < effects.size(); ++e)
                if (effects[e].output_only && effects[e].readings)
                    effects[e].readings(p + offsets[e], in, points, out);
            residuals +=
                model_->normalisedResiduals(out, train_[r], in, options.huber_sigmas, residuals);
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
        for (std::size_t j = 0; j < simulated_.size(); ++j)
            far = far || std::abs(values[simulated_[j]] - l.at[j]) >
                             kRelinearise * scaleOf(free[simulated_[j]], l.at[j]);
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
