// Live thermal compensation: the correction follows the screw model, checked
// against the closed-form warm-up of a uniformly convecting screw; it changes
// only between cuts and never by more than the change limit per update.
#include <gtest/gtest.h>

#include <cmath>

#include "core/compensation/LiveThermalCompensation.h"

namespace driftlab::compensation {
namespace {

/// A screw with no motion: only the ambient acts on it, uniformly, so the
/// field stays uniform and its warm-up has a closed form.
physics::ScrewThermalParameters restingScrew() {
    physics::ScrewThermalParameters p;
    p.cells = 40;
    return p;
}

physics::StepConditions ambient(double dt_s, double ambient_C) {
    physics::StepConditions c;
    c.dt_s = dt_s;
    c.ambient_begin_C = c.ambient_end_C = ambient_C;
    return c;
}

TEST(LiveThermalCompensation, offsetFollowsTheClosedFormWarmUpOfAnAmbientStep) {
    // Ambient 20 → 25 °C. A uniform screw with convection h obeys
    // C dT/dt = −hP (T − 25); backward Euler gives, per step,
    // ΔT_n = 5 (1 − (1 + dt/τ)^−n), τ = ρ c A / (h P) = ρ c d / (4 h),
    // and the error at x is α ΔT (x − x_fixed): E = α ΔT · (x − x_f) mm · 1000 µm/mm.
    const auto p = restingScrew();
    LiveSettings settings;
    settings.update_interval_s = 60;
    settings.offset_position_mm = 500;
    settings.table_positions_mm = {0, 250, 500, 750};
    settings.max_change_um = 1e9;
    LiveThermalCompensation live(p, 20, settings);
    const double tau_s = p.density_kg_m3 * p.specific_heat_J_kgK * p.diameter_m / (4 * p.h_W_m2K);
    const double dt_s = 10;
    int updates = 0;
    for (int n = 1; n <= 720; ++n) {
        const auto update = live.step(ambient(dt_s, 25), MachineState::Idle);
        if (!update) continue;
        ++updates;
        const double rise_K = 5 * (1 - std::pow(1 + dt_s / tau_s, -n));
        for (std::size_t i = 0; i < settings.table_positions_mm.size(); ++i) {
            const double lever_mm = settings.table_positions_mm[i] - p.fixed_end_axis_mm;
            EXPECT_NEAR(update->table_correction_um[i], -p.alpha_per_K * rise_K * lever_mm * 1e3,
                        1e-6)
                << "point " << i << " at " << update->time_s << " s";
        }
        EXPECT_NEAR(update->offset_um, update->table_correction_um[2], 1e-9);
        // The discrete solution converges to the continuous one: at dt = 10 s ≪ τ ≈ 3000 s
        // the exponential differs by well under 1 %.
        const double continuous_K = 5 * (1 - std::exp(-update->time_s / tau_s));
        EXPECT_NEAR(rise_K, continuous_K, 0.01 * continuous_K + 1e-12);
    }
    EXPECT_EQ(updates, 120);  // 7200 s at one update a minute
    // After 2.4 τ the screw has taken 91 % of the step: about −5.9 µm at 500 mm.
    EXPECT_LT(live.applied().offset_um, -5.5);
}

TEST(LiveThermalCompensation, anUpdateDueDuringACutWaitsForTheCutToEnd) {
    LiveSettings settings;
    settings.update_interval_s = 60;
    settings.offset_position_mm = 300;
    settings.max_change_um = 1e9;
    LiveThermalCompensation live(restingScrew(), 20, settings);
    std::vector<LiveUpdate> applied;
    for (int n = 1; n <= 40; ++n) {
        const double t_s = 10.0 * n;
        // Cutting from 50 s to 200 s, idle before and after.
        const MachineState state =
            (t_s > 50 && t_s <= 200) ? MachineState::Cutting : MachineState::Idle;
        const double before_um = live.applied().offset_um;
        if (auto u = live.step(ambient(10, 30), state)) applied.push_back(*u);
        if (state == MachineState::Cutting) {
            EXPECT_EQ(live.applied().offset_um, before_um) << "changed mid-cut at " << t_s << " s";
        }
    }
    ASSERT_GE(applied.size(), 3u);
    EXPECT_DOUBLE_EQ(applied[0].due_s, 60);
    EXPECT_DOUBLE_EQ(applied[0].time_s, 210);  // the first idle step end after the cut
    // The intervals missed during the wait are covered by that update, not replayed.
    EXPECT_DOUBLE_EQ(applied[1].due_s, 240);
    EXPECT_DOUBLE_EQ(applied[1].time_s, 240);
    EXPECT_DOUBLE_EQ(applied[2].time_s, 300);
    EXPECT_FALSE(live.updatePending());
}

TEST(LiveThermalCompensation, aLargeChangeReachesTheMachineInStepsOfTheChangeLimit) {
    // A 20 K ambient step: at 500 mm the target correction grows past −100 µm,
    // far more than the 2 µm an update may change.
    LiveSettings settings;
    settings.update_interval_s = 60;
    settings.offset_position_mm = 500;
    settings.table_positions_mm = {100, 500};
    settings.max_change_um = 2;
    LiveThermalCompensation live(restingScrew(), 20, settings);
    double previous_um = 0;
    int limited = 0;
    for (int n = 1; n <= 6000; ++n) {
        const auto update = live.step(ambient(10, 40), MachineState::Idle);
        if (!update) continue;
        EXPECT_LE(std::abs(update->offset_um - previous_um), 2 + 1e-12);
        limited += update->limited;
        previous_um = update->offset_um;
    }
    EXPECT_GT(limited, 20);
    // After 60000 s (20 τ) the limit has caught up with the model.
    EXPECT_NEAR(live.applied().offset_um, live.targetOffsetUm(), 1e-9);
    EXPECT_LT(live.applied().offset_um, -100);
}

TEST(LiveThermalCompensation, theTableIsTheOnlineModelsThermalErrorWithTheSignTurned) {
    // With motion the field is no longer uniform: the table must equal an
    // independent model stepped with the same conditions.
    auto p = restingScrew();
    const std::vector<MotionSegment> motion{{0, 300, 0, 600, 6000}, {300, 600, 600, 0, -6000}};
    LiveSettings settings;
    settings.update_interval_s = 100;
    settings.table_positions_mm = {0, 150, 300, 450, 600};
    settings.max_change_um = 1e9;
    LiveThermalCompensation live(p, 20, settings);
    physics::ScrewThermalModel reference(p, 20);
    physics::StepConditions step = ambient(5, 20);
    step.motion = motion;
    std::optional<LiveUpdate> last;
    for (int n = 0; n < 120; ++n) {
        reference.step(step);
        if (auto u = live.step(step, MachineState::Moving)) last = u;
    }
    ASSERT_TRUE(last.has_value());
    EXPECT_DOUBLE_EQ(last->time_s, 600);
    const auto error_um = reference.thermalError_um(settings.table_positions_mm);
    for (std::size_t i = 0; i < error_um.size(); ++i)
        EXPECT_NEAR(last->table_correction_um[i], -error_um[i], 1e-12) << "point " << i;
    EXPECT_LT(last->table_correction_um.back(), -0.1);  // the nut heated the screw
}

TEST(LiveThermalCompensation, settingsThatCannotWorkAreRefusedByName) {
    LiveSettings s;
    QString why;
    s.update_interval_s = 0;
    EXPECT_FALSE(s.isValid(&why));
    EXPECT_TRUE(why.contains(QStringLiteral("update interval")));
    s = {};
    s.max_change_um = 0;
    EXPECT_FALSE(s.isValid(&why));
    EXPECT_TRUE(why.contains(QStringLiteral("change limit")));
    s = {};
    s.table_positions_mm = {0, 100, 100};
    EXPECT_FALSE(s.isValid(&why));
    EXPECT_TRUE(why.contains(QStringLiteral("point 2")));
    EXPECT_THROW(LiveThermalCompensation(restingScrew(), 20, s), std::invalid_argument);
}

}  // namespace
}  // namespace driftlab::compensation
