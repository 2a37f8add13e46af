#pragma once
// The effects the simulated rig can hide in a campaign: one per cause id of the
// diagnosis (docs/diagnosis.md), each with a magnitude in physical units.

#include <QString>
#include <QStringList>
#include <map>

namespace driftlab::rig {

struct RigEffects {
    /// forced_convection: h = h0 + h1·|ω|, h1 in W/(m²·K) per rad/s.
    double forced_convection_h1 = 0;
    /// nut_heat_exponent: nut power ∝ |ω|^n, scaled to equal power at 800 rpm (n = 1: base model).
    double nut_heat_exponent = 1;
    /// motor_heat: heat into the fixed end, W per (N·m)² of motor torque.
    double motor_heat_W_per_Nm2 = 0;
    /// sensor_lag:<channel>: first-order lag of a temperature sensor, s.
    std::map<QString, double> sensor_lag_s;
    /// sensor_offset:<channel>: constant offset of a temperature sensor, K.
    std::map<QString, double> sensor_offset_K;
    /// air_refraction: fraction of the Edlén air correction missing (1 = compensation off).
    double air_refraction = 0;
    /// frame_growth: zero shift of the axis per kelvin of structure temperature, µm/K.
    double frame_growth_um_per_K = 0;

    bool any() const;
};

/// The cause ids the rig and the diagnosis know (without channel suffix).
QStringList knownEffectIds();

/// Applies "ID=VALUE" (e.g. "forced_convection=0.1", "sensor_lag:T_nut=300").
/// Returns false and sets `error` for an unknown id, a missing channel suffix,
/// or a value that is not a finite number in its allowed range.
bool applyEffect(RigEffects& effects, const QString& assignment, QString* error);

}  // namespace driftlab::rig
