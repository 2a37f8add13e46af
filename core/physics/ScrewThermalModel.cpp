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
    : parameters_(parameters) {
    parameters_.validate();
    if (!std::isfinite(initial_C))
        throw std::invalid_argument("screw simulation: initial temperature is not finite");
    n_ = parameters_.cells;
    dx_ = parameters_.cellWidth_m();
    const double area = parameters_.area_m2();
    capacity_J_K_ = parameters_.density_kg_m3 * parameters_.specific_heat_J_kgK * area * dx_;
    conductance_W_K_ = parameters_.conductivity_W_mK * area / dx_;
    endConductance_W_K_ = 2 * conductance_W_K_;  // half a cell from centre to face
    surface_m2_ = parameters_.perimeter_m() * dx_;
    temperature_.assign(static_cast<std::size_t>(n_), initial_C);
    reference_ = temperature_;
    initial_ = temperature_;
    temperatureSum_ = initial_C * n_;
    source_J_.assign(temperature_.size(), 0.0);
    rhs_.resize(temperature_.size());
}

void ScrewThermalModel::refactorise(double dt_s, double h_W_m2K) {
    const std::size_t n = temperature_.size();
    const double theta = parameters_.theta;
    std::vector<double> lower(n, -theta * conductance_W_K_);
    std::vector<double> upper(n, -theta * conductance_W_K_);
    std::vector<double> diag(n);
    const double convective = h_W_m2K * surface_m2_;
    for (std::size_t i = 0; i < n; ++i) {
        double leaving = convective;
        leaving += i > 0 ? conductance_W_K_ : 0.0;
        leaving += i + 1 < n ? conductance_W_K_ : 0.0;
        diag[i] = capacity_J_K_ / dt_s + theta * leaving;
    }
    if (parameters_.fixed_end.kind == Kind::FixedTemperature)
        diag.front() += theta * endConductance_W_K_;
    if (parameters_.free_end.kind == Kind::FixedTemperature)
        diag.back() += theta * endConductance_W_K_;
    solver_.factorise(lower, diag, upper);
    factorisedDt_ = dt_s;
    factorisedH_ = h_W_m2K;
}

/// The bearings' heat of a piece of motion; returns its ∫ |ω|^m dt, for
/// forced convection.
double ScrewThermalModel::heatBearings(double omega_rad_s, double duration_s) {
    const double bearing = parameters_.c_bearing_W_per_rad_s * omega_rad_s * duration_s;
    source_J_.front() += bearing;
    source_J_.back() += bearing;
    ledger_.bearings_J += 2 * bearing;
    return parameters_.h1_forced_W_m2K > 0
               ? std::pow(omega_rad_s, parameters_.forced_exponent) * duration_s
               : 0.0;
}

double ScrewThermalModel::collectMotionHeat(const StepConditions& c, double t0, double t1) {
    double speedPowerIntegral = 0;  // ∫ |ω|^m dt, for forced convection
    if (c.nut_path) {
        const NutPath& path = *c.nut_path;
        for (const NutPath::Piece& piece : path.step(c.nut_path_step)) {
            const double power = parameters_.nutPower_W(piece.omega_rad_s);
            const double* w = path.weights(piece);
            double* q = source_J_.data() + piece.first_cell;
            for (std::size_t i = 0; i < piece.cells; ++i) q[i] += power * w[i];
            ledger_.nut_J += power * piece.total_J_per_W;
            speedPowerIntegral += heatBearings(piece.omega_rad_s, piece.duration_s);
        }
        return speedPowerIntegral;
    }
    motionPieces(c.motion, motionCursor_, parameters_, t0, t1, pieces_);
    for (const MotionPiece& piece : pieces_) {
        ledger_.nut_J +=
            depositNutHeat(source_J_, dx_, parameters_.nut_length_m, piece.from_m, piece.to_m,
                           piece.duration_s, parameters_.nutPower_W(piece.omega_rad_s));
        speedPowerIntegral += heatBearings(piece.omega_rad_s, piece.duration_s);
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
    const double width = parameters_.cellWidth_m();
    const double length = std::min(length_m, parameters_.length_m);
    if (joules == 0) return;
    if (length <= width) {
        source_J_.front() += joules;
        return;
    }
    for (std::size_t i = 0; i < source_J_.size() && double(i) * width < length; ++i)
        source_J_[i] +=
            joules * (std::min(double(i + 1) * width, length) - double(i) * width) / length;
}

void ScrewThermalModel::step(const StepConditions& c) {
    if (!(c.dt_s > 0) || !std::isfinite(c.dt_s))
        throw std::invalid_argument("screw simulation: time step must be positive, got " +
                                    std::to_string(c.dt_s) + " s");
    if (!std::isfinite(c.ambient_begin_C) || !std::isfinite(c.ambient_end_C))
        throw std::invalid_argument("screw simulation: ambient temperature is not finite at " +
                                    std::to_string(time_s_) + " s");
    const double t0 = time_s_;
    const double t1 = t0 + c.dt_s;
    // Motion is checked while its heat is deposited: a refused step must not
    // leave heat behind for the next one, nor in the ledger.
    const EnergyLedger ledgerBefore = ledger_;
    double speedPowerIntegral = 0;
    try {
        speedPowerIntegral = collectMotionHeat(c, t0, t1);
    } catch (...) {
        ledger_ = ledgerBefore;
        std::fill(source_J_.begin(), source_J_.end(), 0.0);
        throw;
    }

    const double motor = parameters_.c_motor_W_per_Nm2 * c.mean_torque_squared_Nm2 * c.dt_s;
    depositAtFixedEnd(motor, parameters_.motor_entry_m);
    ledger_.motor_J += motor;
    for (const auto* end : {&parameters_.fixed_end, &parameters_.free_end}) {
        if (end->kind != Kind::HeatFlux) continue;
        const double q = end->heat_W * c.dt_s;
        (end == &parameters_.fixed_end ? source_J_.front() : source_J_.back()) += q;
        ledger_.end_flux_J += q;
    }

    const double h =
        parameters_.h_W_m2K + parameters_.h1_forced_W_m2K * speedPowerIntegral / c.dt_s;
    if (c.dt_s != factorisedDt_ || h != factorisedH_) refactorise(c.dt_s, h);

    const double theta = parameters_.theta;
    const double explicitPart = 1 - theta;
    const double H = h * surface_m2_;
    const double G = conductance_W_K_;
    const double inverseDt = 1 / c.dt_s;
    const std::size_t n = temperature_.size();
    // Three distinct buffers; saying so lets the loop below vectorise.
    const double* __restrict T = temperature_.data();
    const double* __restrict q = source_J_.data();
    double* __restrict r = rhs_.data();
    // C/Δt·T + (1−θ)·(G·(T₋ + T₊ − 2T) − H·(T − Ta₀)) + θ·H·Ta₁ + heat/Δt, with
    // the constants folded so the interior loop is branch-free and vectorises.
    const double self = capacity_J_K_ * inverseDt - explicitPart * (2 * G + H);
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
        const double Ge = endConductance_W_K_;
        r[cell] +=
            -explicitPart * Ge * (T[cell] - end.temperature_C) + theta * Ge * end.temperature_C;
        endsExplicit += Ge * (T[cell] - end.temperature_C);
    };
    fixedEnd(parameters_.fixed_end, 0);
    fixedEnd(parameters_.free_end, n - 1);

    solver_.solve(r);
    temperature_.swap(rhs_);

    // Book the heat that left during the step with the same θ-weighting the
    // scheme used, so the ledger balances to round-off. Σ T at the start of
    // the step is the sum kept from the end of the previous one.
    // Four partial sums: one running sum would wait on every addition.
    double partial[4] = {0, 0, 0, 0};
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4)
        for (int k = 0; k < 4; ++k) partial[k] += temperature_[i + std::size_t(k)];
    for (; i < n; ++i) partial[0] += temperature_[i];
    const double sum = (partial[0] + partial[1]) + (partial[2] + partial[3]);
    const double cells = static_cast<double>(n);
    ledger_.convected_J += c.dt_s * H *
                           (theta * (sum - cells * c.ambient_end_C) +
                            explicitPart * (temperatureSum_ - cells * c.ambient_begin_C));
    temperatureSum_ = sum;
    double endsImplicit = 0;
    if (parameters_.fixed_end.kind == Kind::FixedTemperature)
        endsImplicit +=
            endConductance_W_K_ * (temperature_.front() - parameters_.fixed_end.temperature_C);
    if (parameters_.free_end.kind == Kind::FixedTemperature)
        endsImplicit +=
            endConductance_W_K_ * (temperature_.back() - parameters_.free_end.temperature_C);
    ledger_.through_ends_J += c.dt_s * (theta * endsImplicit + explicitPart * endsExplicit);

    std::fill(source_J_.begin(), source_J_.end(), 0.0);
    time_s_ = t1;
}

double ScrewThermalModel::temperatureAt_C(double x_m) const {
    const double u = x_m / dx_ - 0.5;
    if (u <= 0) return temperature_.front();
    if (u >= n_ - 1) return temperature_.back();
    const auto i = static_cast<std::size_t>(u);
    const double f = u - static_cast<double>(i);
    return temperature_[i] * (1 - f) + temperature_[i + 1] * f;
}

double ScrewThermalModel::meanTemperature_C(double from_m, double to_m) const {
    from_m = std::clamp(from_m, 0.0, parameters_.length_m);
    to_m = std::clamp(to_m, 0.0, parameters_.length_m);
    if (to_m - from_m < 1e-12) return temperatureAt_C(from_m);
    double sum = 0;
    const int first = std::min(n_ - 1, static_cast<int>(from_m / dx_));
    const int last = std::min(n_ - 1, static_cast<int>(to_m / dx_));
    for (int i = first; i <= last; ++i) {
        const double covered = std::min(to_m, (i + 1) * dx_) - std::max(from_m, i * dx_);
        if (covered > 0) sum += covered * temperature_[static_cast<std::size_t>(i)];
    }
    return sum / (to_m - from_m);
}

double ScrewThermalModel::temperatureUnderNut_C(double axis_mm) const {
    const double centre = screwCoordinate_m(axis_mm);
    const double half = 0.5 * parameters_.nut_length_m;
    return meanTemperature_C(centre - half, centre + half);
}

std::vector<double> ScrewThermalModel::expansionPrefix() const {
    // prefix[i] = ∫ α (T − T_ref) from 0 to the left face of cell i, m.
    std::vector<double> prefix(temperature_.size() + 1, 0.0);
    const double scale = parameters_.alpha_per_K * dx_;
    for (std::size_t i = 0; i < temperature_.size(); ++i)
        prefix[i + 1] = prefix[i] + scale * (temperature_[i] - reference_[i]);
    return prefix;
}

double ScrewThermalModel::cumulativeExpansion_m(double x_m,
                                                const std::vector<double>& prefix) const {
    x_m = std::clamp(x_m, 0.0, parameters_.length_m);
    const int i = std::min(n_ - 1, static_cast<int>(x_m / dx_));
    const auto cell = static_cast<std::size_t>(i);
    return prefix[cell] +
           parameters_.alpha_per_K * (x_m - i * dx_) * (temperature_[cell] - reference_[cell]);
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
    reference_ = temperature_;
}

double ScrewThermalModel::storedEnergy_J() const {
    double sum = 0;
    for (std::size_t i = 0; i < temperature_.size(); ++i) sum += temperature_[i] - initial_[i];
    return capacity_J_K_ * sum;
}

}  // namespace driftlab::physics
