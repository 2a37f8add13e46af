#include "core/models/HeatTransferModel.h"

#include <ceres/ceres.h>

#include <Eigen/SVD>
#include <chrono>
#include <cmath>

#include "core/models/CeresResiduals.h"
#include "core/models/ModelError.h"

namespace driftlab::models {
namespace {

/// Huber on a residual in σ units, as a residual whose square is 2ρ(r²): one
/// residual block holds the whole simulation, so Ceres' per-block LossFunction
/// would be robust per run, not per reading.
double robust(double r, double delta) {
    const double a = std::abs(r);
    return a <= delta ? r : std::copysign(std::sqrt(2 * delta * a - delta * delta), r);
}

/// What the data cannot separate: the parameters of the weakest direction of
/// the column-scaled Jacobian when it is numerically singular, else empty.
QString weakestDirection(const Eigen::MatrixXd& jacobian, const std::vector<FreeParameter>& names,
                         const std::vector<double>& values) {
    Eigen::MatrixXd scaled = jacobian;
    for (Eigen::Index c = 0; c < scaled.cols(); ++c)
        scaled.col(c) *= std::max(std::abs(values[std::size_t(c)]), 1e-3);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeThinV);
    const Eigen::VectorXd& singular = svd.singularValues();
    // 1e-7 on J is 1e-14 on JᵀJ, where Ceres' covariance gives up.
    if (singular[0] > 0 && singular[singular.size() - 1] > 1e-7 * singular[0]) return {};
    const Eigen::VectorXd weakest = svd.matrixV().col(svd.matrixV().cols() - 1);
    QStringList involved;
    for (Eigen::Index c = 0; c < weakest.size(); ++c)
        if (std::abs(weakest[c]) > 0.3) involved << names[std::size_t(c)].name;
    return involved.join(QStringLiteral(" and "));
}

}  // namespace

ScrewModelVariant baseScrewModel(bool material) {
    ScrewModelVariant v;
    v.parameters = {{QStringLiteral("c_nut"), QStringLiteral("W/(rad/s)"), 0.05, 0, 2},
                    {QStringLiteral("c_b"), QStringLiteral("W/(rad/s)"), 0.05, 0, 1},
                    {QStringLiteral("h"), QStringLiteral("W/(m²·K)"), 8, 0.5, 200}};
    if (material) {
        v.parameters.push_back(
            {QStringLiteral("rho_c"), QStringLiteral("J/(m³·K)"), 3.6e6, 1e6, 1e7});
        v.parameters.push_back({QStringLiteral("k"), QStringLiteral("W/(m·K)"), 45, 5, 200});
    }
    v.physics = [material](const double* p, physics::ScrewThermalParameters& s) {
        s.c_nut_W_per_rad_s = p[0];
        s.c_bearing_W_per_rad_s = p[1];
        s.h_W_m2K = p[2];
        if (material) {
            s.specific_heat_J_kgK = p[3] / s.density_kg_m3;
            s.conductivity_W_mK = p[4];
        }
    };
    return v;
}

HeatTransferModel::HeatTransferModel(HeatTransferOptions options, ScrewModelVariant variant)
    : m_options(options), m_variant(std::move(variant)) {}

HeatTransferModel::HeatTransferModel(HeatTransferOptions options, ScrewModelVariant variant,
                                     std::vector<double> values)
    : m_options(options), m_variant(std::move(variant)), m_values(std::move(values)) {
    markFitted({});
}

QString HeatTransferModel::describe() const {
    return QStringLiteral(
               "1-D conduction along the screw, nut and bearings heating in "
               "proportion to speed, convection to the ambient channel; %1 "
               "identified from screw temperatures and positioning errors")
        .arg([&] {
            QStringList n;
            for (const auto& p : m_variant.parameters) n << p.name;
            return n.join(QStringLiteral(", "));
        }());
}

physics::ScrewThermalParameters HeatTransferModel::parametersWith(const double* values,
                                                                  const RunData& run) const {
    physics::ScrewThermalParameters p = screwParameters(run, {}, m_options.cells);
    p.density_kg_m3 = run.screw->density_kg_m3;
    p.specific_heat_J_kgK = run.screw->specific_heat_J_kgK;
    p.conductivity_W_mK = run.screw->conductivity_W_mK;
    m_variant.physics(values, p);
    return p;
}

ScrewRunInputs HeatTransferModel::prepared(const RunData& run) const {
    return prepareScrewRun(run, m_options.dt_s, name(), m_options.room, m_options.cells);
}

std::optional<physics::ScrewThermalParameters> HeatTransferModel::fittedScrew(const RunData& run,
                                                                              QString* why) const {
    const QString problem =
        !isFitted()  ? QStringLiteral("model '%1' is not fitted yet").arg(name())
        : !run.screw ? QStringLiteral("run '%1' has no screw to simulate").arg(run.run_id)
                     : QString();
    if (!problem.isEmpty()) {
        if (why) *why = problem;
        return std::nullopt;
    }
    return parametersWith(m_values.data(), run);
}

ScrewRunOutputs HeatTransferModel::simulate(const double* values, const RunData& run,
                                            const ScrewRunInputs& inputs,
                                            const std::vector<PredictionPoint>& at) const {
    // An effect on the inputs works on a copy: the prepared run serves every
    // evaluation of the fit.
    std::optional<ScrewRunInputs> changed;
    if (m_variant.inputs) m_variant.inputs(values, changed.emplace(inputs));
    const ScrewRunInputs& in = changed ? *changed : inputs;
    ScrewRunOutputs out = simulateScrewRun(in, parametersWith(values, run), at);
    if (m_variant.readings) m_variant.readings(values, in, at, out);
    return out;
}

Eigen::VectorXd HeatTransferModel::predictRun(const RunData& run,
                                              const std::vector<PredictionPoint>& at) const {
    const auto out = simulate(m_values.data(), run, prepared(run), at);
    return Eigen::Map<const Eigen::VectorXd>(out.error_um.data(),
                                             Eigen::Index(out.error_um.size()));
}

std::size_t HeatTransferModel::writeResiduals(const double* values, const RunData& run,
                                              const ScrewRunInputs& inputs, double huberSigmas,
                                              double* out) const {
    return normalisedResiduals(simulate(values, run, inputs, run.observationPoints()), run, inputs,
                               huberSigmas, out);
}

std::size_t HeatTransferModel::normalisedResiduals(const ScrewRunOutputs& sim, const RunData& run,
                                                   const ScrewRunInputs& inputs, double huberSigmas,
                                                   double* out) const {
    std::size_t i = 0;
    for (std::size_t o = 0; o < run.observations.size(); ++o)
        out[i++] =
            robust((run.observations[o].error_um - sim.error_um[o]) / m_options.error_sigma_um,
                   huberSigmas);
    if (!m_options.fit_temperatures) return i;
    for (std::size_t s = 0; s < inputs.sensors.size(); ++s)
        for (std::size_t j = 0; j < sim.sensor_C[s].size(); ++j)
            out[i++] = robust((inputs.sensors[s].measured_C[j] - sim.sensor_C[s][j]) /
                                  m_options.temperature_sigma_K,
                              huberSigmas);
    return i;
}

std::size_t HeatTransferModel::readingCount(const RunData& run,
                                            const ScrewRunInputs& inputs) const {
    std::size_t count = run.observations.size();
    if (m_options.fit_temperatures)
        for (const auto& s : inputs.sensors) count += s.time_s.size();
    return count;
}

double HeatTransferModel::cost(const std::vector<double>& values,
                               const std::vector<RunData>& runs) const {
    double sum = 0;
    std::vector<double> r;
    for (const RunData& run : runs) {
        const ScrewRunInputs inputs = prepared(run);
        r.resize(readingCount(run, inputs));
        writeResiduals(values.data(), run, inputs, m_options.huber_sigmas, r.data());
        for (double v : r) sum += v * v / 2;
    }
    return sum;
}

ReadingResiduals HeatTransferModel::residuals(const RunData& run) const {
    if (m_values.empty()) throw ModelError(QStringLiteral("model '%1' is not fitted").arg(name()));
    const ScrewRunInputs inputs = prepared(run);
    const std::size_t count = readingCount(run, inputs);
    std::vector<double> r(count);
    writeResiduals(m_values.data(), run, inputs, INFINITY, r.data());
    ReadingResiduals out;
    out.run_id = run.run_id;
    out.points = run.observationPoints();
    std::size_t i = 0;
    for (; i < out.points.size(); ++i) out.error_um.push_back(r[i] * m_options.error_sigma_um);
    if (m_options.fit_temperatures)
        for (const auto& s : inputs.sensors) {
            ReadingResiduals::Sensor sensor{s.channel_id, s.role, s.time_s, {}};
            for (std::size_t j = 0; j < s.time_s.size(); ++j)
                sensor.residual_K.push_back(r[i++] * m_options.temperature_sigma_K);
            out.sensors.push_back(std::move(sensor));
        }
    for (double v : r) out.normalizedSquares += v * v;
    out.count = count;
    return out;
}

FitSummary HeatTransferModel::fitRuns(const std::vector<RunData>& training) {
    for (const RunData& run : training)
        if (!run.positionDependent())
            throw ModelError(QStringLiteral("model '%1' predicts the positioning error "
                                            "of the screw, not channel '%2'")
                                 .arg(name(), run.target_channel));
    std::vector<ScrewRunInputs> inputs;
    int residualCount = 0;
    int temperatureCount = 0;
    for (const RunData& run : training) {
        inputs.push_back(prepared(run));
        residualCount += int(run.observations.size());
        if (m_options.fit_temperatures)
            for (const auto& s : inputs.back().sensors) temperatureCount += int(s.time_s.size());
    }
    residualCount += temperatureCount;
    if (residualCount == 0)
        throw ModelError(
            QStringLiteral("model '%1': the training runs have no readings").arg(name()));

    const auto& free = m_variant.parameters;
    const int n = int(free.size());
    std::vector<double> values;
    for (const auto& p : free) values.push_back(p.initial);

    auto evaluate = [&](const double* p, double* r) {
        try {
            for (std::size_t k = 0; k < training.size(); ++k)
                r += writeResiduals(p, training[k], inputs[k], m_options.huber_sigmas, r);
            return true;
        } catch (const std::invalid_argument&) {
            return false;  // parameters the physics refuses: Ceres shortens the step
        }
    };

    ceres::Problem problem;
    ceres::CostFunction* simulation = numericCost<ceres::FORWARD>(evaluate, n, residualCount);
    problem.AddResidualBlock(simulation, nullptr, values.data());
    for (int i = 0; i < n; ++i) {
        problem.SetParameterLowerBound(values.data(), i, free[std::size_t(i)].lower);
        problem.SetParameterUpperBound(values.data(), i, free[std::size_t(i)].upper);
    }
    ceres::Solver::Options solverOptions;
    solverOptions.linear_solver_type = ceres::DENSE_QR;
    solverOptions.max_num_iterations = m_options.max_iterations;
    solverOptions.function_tolerance = m_options.function_tolerance;
    solverOptions.parameter_tolerance = m_options.parameter_tolerance;
    solverOptions.logging_type = ceres::SILENT;
    CancelCallback cancel([this] { return cancelRequested(); });
    solverOptions.callbacks.push_back(&cancel);
    ceres::Solver::Summary solved;
    const auto started = std::chrono::steady_clock::now();
    ceres::Solve(solverOptions, &problem, &solved);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (cancelRequested())
        throw ModelError(QStringLiteral("model '%1': fit cancelled after %2 iterations")
                             .arg(name())
                             .arg(solved.iterations.size()));
    if (!solved.IsSolutionUsable())
        throw ModelError(QStringLiteral("model '%1': identification failed: %2")
                             .arg(name(), QString::fromStdString(solved.message)));

    FitSummary summary;
    summary.iterations = int(solved.iterations.size());
    summary.metrics[QStringLiteral("final_cost")] = solved.final_cost;
    summary.metrics[QStringLiteral("initial_cost")] = solved.initial_cost;
    summary.metrics[QStringLiteral("identification_s")] = seconds;
    summary.metrics[QStringLiteral("temperature_readings")] = temperatureCount;

    // 1σ from the covariance, scaled by the residual variance (the weights are
    // nominal noise levels, the fit tells the real ones).
    const double dof = std::max(1, residualCount - n);
    const double variance = 2 * solved.final_cost / dof;
    // Identifiability first, from the SVD of the column-scaled Jacobian (Ceres'
    // covariance would only log that the matrix is rank deficient).
    ceres::CRSMatrix crs;
    problem.Evaluate(ceres::Problem::EvaluateOptions(), nullptr, nullptr, nullptr, &crs);
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
    for (int row = 0; row < crs.num_rows; ++row)
        for (int k = crs.rows[std::size_t(row)]; k < crs.rows[std::size_t(row) + 1]; ++k)
            jacobian(row, crs.cols[std::size_t(k)]) = crs.values[std::size_t(k)];
    const QString weak = weakestDirection(jacobian, free, values);
    std::vector<double> block(std::size_t(n * n), std::nan(""));
    bool identifiable = weak.isEmpty();
    if (identifiable) {
        ceres::Covariance::Options covarianceOptions;
        covarianceOptions.algorithm_type = ceres::DENSE_SVD;
        ceres::Covariance covariance(covarianceOptions);
        const std::vector<std::pair<const double*, const double*>> blocks{
            {values.data(), values.data()}};
        identifiable = covariance.Compute(blocks, &problem) &&
                       covariance.GetCovarianceBlock(values.data(), values.data(), block.data());
    }
    if (!identifiable)
        summary.notes << QStringLiteral(
                             "not identifiable: these runs cannot separate %1; their "
                             "values are one of many that fit equally well")
                             .arg(weak.isEmpty() ? QStringLiteral("the parameters") : weak);
    for (int i = 0; i < n; ++i) {
        const auto& p = free[std::size_t(i)];
        const double sigma =
            identifiable ? std::sqrt(std::max(0.0, block[std::size_t(i * n + i)] * variance))
                         : std::nan("");
        summary.parameters[p.name] = {values[std::size_t(i)], sigma, p.unit};
        const double span = p.upper - p.lower;
        if (values[std::size_t(i)] - p.lower < 1e-6 * span ||
            p.upper - values[std::size_t(i)] < 1e-6 * span)
            summary.notes << QStringLiteral("%1 = %2 %3 is at its bound")
                                 .arg(p.name, messageNumber(values[std::size_t(i)]), p.unit);
    }
    for (const auto& s : inputs.front().sensors) summary.inputs << s.channel_id;
    QStringList rebuilt;
    for (const RunData& run : training)
        if (run.motion.empty()) rebuilt << run.run_id;
    if (!rebuilt.isEmpty())
        summary.notes << QStringLiteral(
                             "run(s) %1 have no motion.csv: the nut's motion is rebuilt from the "
                             "position column, and where the feed column shows strokes between "
                             "two position samples they are filled in (motion.csv gives the "
                             "heat input exactly)")
                             .arg(rebuilt.join(QStringLiteral(", ")));
    summary.message = QStringLiteral(
                          "%1 identified on %2 run(s) in %3 iterations "
                          "(%4 s)")
                          .arg(name())
                          .arg(training.size())
                          .arg(summary.iterations)
                          .arg(seconds, 0, 'f', 2);
    m_values = values;
    return summary;
}

}  // namespace driftlab::models
