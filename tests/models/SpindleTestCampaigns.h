#pragma once
// Synthetic spindle campaigns for the drift models' tests: thermometers on
// the spindle, its speed, a z drift probe, and runs whose speed programmes
// and drift are closed forms of the speed.

#include <QString>
#include <array>
#include <map>
#include <utility>
#include <vector>

#include "core/domain/Campaign.h"
#include "tests/models/ModelTestSupport.h"

namespace driftlab::test {

/// Thermometers T1…Tn on the spindle, the spindle's speed `n_spindle` (when
/// asked for) and a z drift probe D_z.
Campaign spindleCampaign(int thermometers, bool speedChannel);

/// Spindle run SP<n>, the campaign's n-th, sampled every 15 s.
void addSpindleRun(Campaign& c, double duration_s, const std::map<QString, Profile>& columns);

/// Speed programmes, (rpm, s) blocks, and the exact first-order response of
/// an input that is a function of the speed, from rest.
using Programme = std::vector<std::pair<double, double>>;
double responseTo(const Programme& blocks, double (*input)(double rpm), double tau_s, double t);
/// The speed in 1000 rpm, and its square.
double krpm(double rpm);
double krpmSquared(double rpm);
/// The speed of the programme at time t (0 after its end).
double speedAt(const Programme& blocks, double t);

constexpr double kRotorLag_s = 900;
constexpr double kRotorGain_um_per_krpm2 = -0.05;
constexpr std::array<double, 4> kBearingLag_s{240, 700, 2000, 5000};
constexpr std::array<double, 4> kBearingRise_K_per_krpm{0.8, 0.5, 0.3, 0.2};
constexpr std::array<double, 4> kBearingGain_um_per_K{-1.0, 0.6, -0.4, 1.2};

/// Four spindle runs of different speed programmes. Four thermometers follow
/// the bearings' friction heat, ∝ n, each through its own lag; the z drift is
/// a static sum of their rises (kBearingGain_um_per_K) plus a rotor heated by
/// its own losses, ∝ n², through a lag of 900 s, which no thermometer sees:
/// −0.05 µm per krpm². The held-out SP4 goes to 9000 rpm, beyond every other.
Campaign rotorCampaign();

}  // namespace driftlab::test
