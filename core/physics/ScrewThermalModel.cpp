#include "core/physics/ScrewThermalModel.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/physics/NutHeatDeposition.h"

namespace driftlab::physics {

namespace {
using Kind = EndCondition::Kind;
}

ScrewThermalModel::ScrewThermalModel(const ScrewThermalParameters& parameters, double initial_C)
    : m_parameters(parameters) {
    m_parameters.validate();
    if (!std::isfinite(initial_C))
        throw std::invalid_argument("screw simulation: initial temperature is not finite");
    n_ = m_parameters.cells;
    m_dx = m_parameters.cellWidth_m();
    const double area = m_parameters.area_m2();
    m_capacity_J_K = m_parameters.density_kg_m3 * m_parameters.specific_heat_J_kgK * area * m_dx;
    m_conductance_W_K = m_parameters.conductivity_W_mK * area / m_dx;
    m_endConductance_W_K = 2 * m_conductance_W_K;  // half a cell from centre to face
    m_surface_m2 = m_parameters.perimeter_m() * m_dx;
    m_temperature.assign(static_cast<std::size_t>(n_), initial_C);
    m_reference = m_temperature;
    m_initial = m_temperature;
    m_temperatureSum = initial_C * n_;
    m_source_J.assign(m_temperature.size(), 0.0);
    m_rhs.resize(m_temperature.size());
}

void ScrewThermalModel::refactorise(double dt_s, double h_W_m2K) {
    const std::size_t n = m_temperature.size();
    const double theta = m_parameters.theta;
    std::vector<double>& lower = m_lower;
    std::vector<double>& upper = m_upper;
    std::vector<double>& diag = m_diag;
    lower.assign(n, -theta * m_conductance_W_K);
    upper.assign(n, -theta * m_conductance_W_K);
    diag.resize(n);
    const double convective = h_W_m2K * m_surface_m2;
    for (std::size_t i = 0; i < n; ++i) {
        double leaving = convective;
        leaving += i > 0 ? m_conductance_W_K : 0.0;
        leaving += i + 1 < n ? m_conductance_W_K : 0.0;
        diag[i] = m_capacity_J_K / dt_s + theta * leaving;
    }
    if (m_parameters.fixed_end.kind == Kind::FixedTemperature)
        diag.front() += theta * m_endConductance_W_K;
    if (m_parameters.free_end.kind == Kind::FixedTemperature)
        diag.back() += theta * m_endConductance_W_K;
    m_solver.factorise(lower, diag, upper);
    m_factorisedDt = dt_s;
    m_factorisedH = h_W_m2K;
}

/// The bearings' heat of a piece of motion; returns its ∫ |ω|^m dt, for
/// forced convection.
double ScrewThermalModel::heatBearings(double omega_rad_s, double duration_s, double forcedPower) {
    const double bearing = m_parameters.c_bearing_W_per_rad_s * omega_rad_s * duration_s;
    m_source_J.front() += bearing;
    m_source_J.back() += bearing;
    m_ledger.bearings_J += 2 * bearing;
    return forcedPower * duration_s;
}

const ScrewThermalModel::SpeedTerms& ScrewThermalModel::speedTerms(double omega_rad_s) {
    for (const SpeedTerms& terms : m_speedTerms)
        if (terms.omega_rad_s == omega_rad_s) return terms;
    SpeedTerms& terms = m_speedTerms[m_nextSpeedTerm];
    m_nextSpeedTerm = (m_nextSpeedTerm + 1) % m_speedTerms.size();
    terms.omega_rad_s = omega_rad_s;
    terms.nut_W = m_parameters.nutPower_W(omega_rad_s);
    terms.forced = m_parameters.h1_forced_W_m2K > 0
                       ? std::pow(omega_rad_s, m_parameters.forced_exponent)
                       : 0.0;
    return terms;
}

double ScrewThermalModel::collectMotionHeat(const StepConditions& c, double t0, double t1) {
    double speedPowerIntegral = 0;  // ∫ |ω|^m dt, for forced convection
    if (c.nut_path) {
        const NutPath& path = *c.nut_path;
        for (const NutPath::Piece& piece : path.step(c.nut_path_step)) {
            const SpeedTerms& terms = speedTerms(piece.omega_rad_s);
            const double power = terms.nut_W;
            const double* w = path.weights(piece);
            double* q = m_source_J.data() + piece.first_cell;
            for (std::size_t i = 0; i < piece.cells; ++i) q[i] += power * w[i];
            m_ledger.nut_J += power * piece.total_J_per_W;
            speedPowerIntegral += heatBearings(piece.omega_rad_s, piece.duration_s, terms.forced);
        }
        return speedPowerIntegral;
    }
    motionPieces(c.motion, m_motionCursor, m_parameters, t0, t1, m_pieces);
    for (const MotionPiece& piece : m_pieces) {
        const SpeedTerms& terms = speedTerms(piece.omega_rad_s);
        m_ledger.nut_J += depositNutHeat(m_source_J, m_dx, m_parameters.nut_length_m, piece.from_m,
                                         piece.to_m, piece.duration_s, terms.nut_W);
        speedPowerIntegral += heatBearings(piece.omega_rad_s, piece.duration_s, terms.forced);
    }
    return speedPowerIntegral;
}

// On CPUs with FMA (x86-64 since 2013) the step runs a clone compiled for it:
// the tridiagonal sweeps are latency chains of multiply-adds, and a fused
// multiply-add halves their latency. Other CPUs run the default build.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("arch=haswell", "default")))
#endif
void ScrewThermalModel::depositAtFixedEnd(double joules, double length_m) {
    const double width = m_parameters.cellWidth_m();
    const double length = std::min(length_m, m_parameters.length_m);
    if (joules == 0) return;
    if (length <= width) {
        m_source_J.front() += joules;
        return;
    }
    for (std::size_t i = 0; i < m_source_J.size() && double(i) * width < length; ++i)
        m_source_J[i] +=
            joules * (std::min(double(i + 1) * width, length) - double(i) * width) / length;
}

void ScrewThermalModel::step(const StepConditions& c) {
    if (!(c.dt_s > 0) || !std::isfinite(c.dt_s))
        throw std::invalid_argument("screw simulation: time step must be positive, got " +
                                    std::to_string(c.dt_s) + " s");
    if (!std::isfinite(c.ambient_begin_C) || !std::isfinite(c.ambient_end_C))
        throw std::invalid_argument("screw simulation: ambient temperature is not finite at " +
                                    std::to_string(m_time_s) + " s");
    const double t0 = m_time_s;
    const double t1 = t0 + c.dt_s;
    // Motion is checked while its heat is deposited: a refused step must not
    // leave heat behind for the next one, nor in the ledger.
    const EnergyLedger ledgerBefore = m_ledger;
    double speedPowerIntegral = 0;
    try {
        speedPowerIntegral = collectMotionHeat(c, t0, t1);
    } catch (...) {
        m_ledger = ledgerBefore;
        std::fill(m_source_J.begin(), m_source_J.end(), 0.0);
        throw;
    }

    const double motor = m_parameters.c_motor_W_per_Nm2 * c.mean_torque_squared_Nm2 * c.dt_s;
    depositAtFixedEnd(motor, m_parameters.motor_entry_m);
    m_ledger.motor_J += motor;
    for (const auto* end : {&m_parameters.fixed_end, &m_parameters.free_end}) {
        if (end->kind != Kind::HeatFlux) continue;
        const double q = end->heat_W * c.dt_s;
        (end == &m_parameters.fixed_end ? m_source_J.front() : m_source_J.back()) += q;
        m_ledger.end_flux_J += q;
    }

    const double h =
        m_parameters.h_W_m2K + m_parameters.h1_forced_W_m2K * speedPowerIntegral / c.dt_s;
    if (c.dt_s != m_factorisedDt || h != m_factorisedH) refactorise(c.dt_s, h);

    const double theta = m_parameters.theta;
    const double explicitPart = 1 - theta;
    const double H = h * m_surface_m2;
    const double G = m_conductance_W_K;
    const double inverseDt = 1 / c.dt_s;
    const std::size_t n = m_temperature.size();
    // Three distinct buffers; saying so lets the loop below vectorise.
    const double* __restrict T = m_temperature.data();
    const double* __restrict q = m_source_J.data();
    double* __restrict r = m_rhs.data();
    // C/Δt·T + (1−θ)·(G·(T₋ + T₊ − 2T) − H·(T − Ta₀)) + θ·H·Ta₁ + heat/Δt, with
    // the constants folded so the interior loop is branch-free and vectorises.
    const double self = m_capacity_J_K * inverseDt - explicitPart * (2 * G + H);
    const double neighbour = explicitPart * G;
    const double ambient = explicitPart * H * c.ambient_begin_C + theta * H * c.ambient_end_C;
    for (std::size_t i = 1; i + 1 < n; ++i)
        r[i] = self * T[i] + neighbour * (T[i - 1] + T[i + 1]) + ambient + q[i] * inverseDt;
    // End cells have one neighbour.
    r[0] = (self + neighbour) * T[0] + neighbour * T[1] + ambient + q[0] * inverseDt;
    r[n - 1] =
        (self + neighbour) * T[n - 1] + neighbour * T[n - 2] + ambient + q[n - 1] * inverseDt;
    // Fixed-temperature ends: conductance from the end cell to the face.
    double endsExplicit = 0;
    auto fixedEnd = [&](const EndCondition& end, std::size_t cell) {
        if (end.kind != Kind::FixedTemperature) return;
        const double Ge = m_endConductance_W_K;
        r[cell] +=
            -explicitPart * Ge * (T[cell] - end.temperature_C) + theta * Ge * end.temperature_C;
        endsExplicit += Ge * (T[cell] - end.temperature_C);
    };
    fixedEnd(m_parameters.fixed_end, 0);
    fixedEnd(m_parameters.free_end, n - 1);

    m_solver.solve(r);
    m_temperature.swap(m_rhs);

    // Book the heat that left during the step with the same θ-weighting the
    // scheme used, so the ledger balances to round-off. Σ T at the start of
    // the step is the sum kept from the end of the previous one.
    // Four partial sums: one running sum would wait on every addition.
    double partial[4] = {0, 0, 0, 0};
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4)
        for (int k = 0; k < 4; ++k) partial[k] += m_temperature[i + std::size_t(k)];
    for (; i < n; ++i) partial[0] += m_temperature[i];
    const double sum = (partial[0] + partial[1]) + (partial[2] + partial[3]);
    const double cells = static_cast<double>(n);
    m_ledger.convected_J += c.dt_s * H *
                            (theta * (sum - cells * c.ambient_end_C) +
                             explicitPart * (m_temperatureSum - cells * c.ambient_begin_C));
    m_temperatureSum = sum;
    double endsImplicit = 0;
    if (m_parameters.fixed_end.kind == Kind::FixedTemperature)
        endsImplicit +=
            m_endConductance_W_K * (m_temperature.front() - m_parameters.fixed_end.temperature_C);
    if (m_parameters.free_end.kind == Kind::FixedTemperature)
        endsImplicit +=
            m_endConductance_W_K * (m_temperature.back() - m_parameters.free_end.temperature_C);
    m_ledger.through_ends_J += c.dt_s * (theta * endsImplicit + explicitPart * endsExplicit);

    std::fill(m_source_J.begin(), m_source_J.end(), 0.0);
    m_time_s = t1;
}

double ScrewThermalModel::temperatureAt_C(double x_m) const {
    const double u = x_m / m_dx - 0.5;
    if (u <= 0) return m_temperature.front();
    if (u >= n_ - 1) return m_temperature.back();
    const auto i = static_cast<std::size_t>(u);
    const double f = u - static_cast<double>(i);
    return m_temperature[i] * (1 - f) + m_temperature[i + 1] * f;
}

double ScrewThermalModel::meanTemperature_C(double from_m, double to_m) const {
    from_m = std::clamp(from_m, 0.0, m_parameters.length_m);
    to_m = std::clamp(to_m, 0.0, m_parameters.length_m);
    if (to_m - from_m < 1e-12) return temperatureAt_C(from_m);
    double sum = 0;
    const int first = std::min(n_ - 1, static_cast<int>(from_m / m_dx));
    const int last = std::min(n_ - 1, static_cast<int>(to_m / m_dx));
    for (int i = first; i <= last; ++i) {
        const double covered = std::min(to_m, (i + 1) * m_dx) - std::max(from_m, i * m_dx);
        if (covered > 0) sum += covered * m_temperature[static_cast<std::size_t>(i)];
    }
    return sum / (to_m - from_m);
}

double ScrewThermalModel::temperatureUnderNut_C(double axis_mm) const {
    const double centre = screwCoordinate_m(axis_mm);
    const double half = 0.5 * m_parameters.nut_length_m;
    return meanTemperature_C(centre - half, centre + half);
}

std::vector<double> ScrewThermalModel::expansionPrefix() const {
    // prefix[i] = ∫ α (T − T_ref) from 0 to the left face of cell i, m.
    std::vector<double> prefix(m_temperature.size() + 1, 0.0);
    const double scale = m_parameters.alpha_per_K * m_dx;
    for (std::size_t i = 0; i < m_temperature.size(); ++i)
        prefix[i + 1] = prefix[i] + scale * (m_temperature[i] - m_reference[i]);
    return prefix;
}

double ScrewThermalModel::cumulativeExpansion_m(double x_m,
                                                const std::vector<double>& prefix) const {
    x_m = std::clamp(x_m, 0.0, m_parameters.length_m);
    const int i = std::min(n_ - 1, static_cast<int>(x_m / m_dx));
    const auto cell = static_cast<std::size_t>(i);
    return prefix[cell] +
           m_parameters.alpha_per_K * (x_m - i * m_dx) * (m_temperature[cell] - m_reference[cell]);
}

double ScrewThermalModel::thermalError_um(double axis_mm) const {
    return cumulativeExpansion_m(screwCoordinate_m(axis_mm), expansionPrefix()) * 1e6;
}

std::vector<double> ScrewThermalModel::thermalError_um(const std::vector<double>& axis_mm) const {
    const auto prefix = expansionPrefix();
    std::vector<double> error(axis_mm.size());
    for (std::size_t k = 0; k < axis_mm.size(); ++k)
        error[k] = cumulativeExpansion_m(screwCoordinate_m(axis_mm[k]), prefix) * 1e6;
    return error;
}

void ScrewThermalModel::resetReference() {
    m_reference = m_temperature;
}

double ScrewThermalModel::storedEnergy_J() const {
    double sum = 0;
    for (std::size_t i = 0; i < m_temperature.size(); ++i) sum += m_temperature[i] - m_initial[i];
    return m_capacity_J_K * sum;
}

}  // namespace driftlab::physics
