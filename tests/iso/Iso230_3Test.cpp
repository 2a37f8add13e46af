// ISO 230-3 drift evaluation with values worked by hand (the comment above
// each case shows the arithmetic), the bad input that must be refused, and a
// sanity check on the example bundle's moving run S1 and spindle run SP1.
//
// Stabilised at t_s (core/iso/Iso230_3.h): the earliest sample time such that
// from every sample time on the drift, linear between samples, varies by less
// than D over [t_i, t_i + W], with at least W of the run after t_s.

#include <gtest/gtest.h>

#include "core/bundle/BundleReader.h"
#include "core/iso/Iso230_3.h"

namespace driftlab::iso {
namespace {

constexpr double kExactUm = 1e-9;
constexpr auto kUp = Direction::Positive;
constexpr auto kDown = Direction::Negative;

/// Readings of one target and direction at t0, t0 + 600, ...: cycles 0, 1, ...
void add(Run& run, double target_mm, Direction d, double t0_s, std::vector<double> dev_um) {
    for (std::size_t c = 0; c < dev_um.size(); ++c)
        run.positioning.push_back({t0_s + 600.0 * double(c), int(c), target_mm, d, dev_um[c]});
}

DriftSettings settings(double window_s, double tolerance_um) {
    DriftSettings s;
    s.window_s = window_s;
    s.tolerance_um = tolerance_um;
    return s;
}

DriftSeries series(std::vector<double> drift_um, double step_s = 600) {
    DriftSeries s;
    for (std::size_t i = 0; i < drift_um.size(); ++i) s.time_s.push_back(step_s * double(i));
    s.drift_um = std::move(drift_um);
    return s;
}

double stabilisedAt(std::vector<double> drift_um, double window_s, double tolerance_um) {
    DriftSeries s = series(std::move(drift_um));
    summarise(s, settings(window_s, tolerance_um));
    return s.stabilised_time_s;
}

// The brief's target: drift 0, 2, 5, 7, 8, 8.2, 8.3 µm at t = 0, 600, ..., 3600 s.
// Change over the window starting at each reading (W = 600: to the next one):
//   t      0    600  1200  1800  2400  3000  3600
//   Δ      2    3    2     1     0.2   0.1   0 (end of run)
// W = 600, D = 1: 1800 fails (1 is not below 1), from 2400 on all pass, and
// 3600 − 2400 = 1200 ≥ W: stabilised at 2400 s.
const std::vector<double> kBrief{0, 2, 5, 7, 8, 8.2, 8.3};

TEST(Iso230_3Golden, briefTargetMaximumAndStabilisation) {
    DriftSeries s = series(kBrief);
    summarise(s, settings(600, 1));
    EXPECT_NEAR(s.max_drift_um, 8.3, kExactUm);
    EXPECT_EQ(s.max_drift_time_s, 3600);
    EXPECT_NEAR(s.range_um, 8.3, kExactUm);
    EXPECT_NEAR(s.final_drift_um, 8.3, kExactUm);
    EXPECT_EQ(s.stabilised_time_s, 2400);
    // W = 1200, D = 1: from 1800 the window holds 7, 8, 8.2 (1.2 ✗); from 2400
    // 8, 8.2, 8.3 (0.3 ✓), and 3600 − 2400 = 1200 ≥ W: 2400 s.
    EXPECT_EQ(stabilisedAt(kBrief, 1200, 1), 2400);
    // W = 600, D = 0.15: 8 → 8.2 is 0.2 ✗, 8.2 → 8.3 is 0.1 ✓, 3600 − 3000 = 600: 3000 s.
    EXPECT_EQ(stabilisedAt(kBrief, 600, 0.15), 3000);
    // W = 900, D = 0.15: still 3000 by the windows, but only 600 s of run
    // follow it, less than W: not stabilised within the run.
    EXPECT_TRUE(std::isnan(stabilisedAt(kBrief, 900, 0.15)));
    // W = 300, D = 1, readings 600 s apart: judged by interpolation. From 1200:
    // 5 → 6 at 1500 (1 ✗); from 1800: 7 → 7.5 (0.5 ✓), then 0.1, 0.05: 1800 s.
    EXPECT_EQ(stabilisedAt(kBrief, 300, 1), 1800);
}

TEST(Iso230_3Golden, neverStabilisesOrOnlyLooksStable) {
    // A steady 2 µm per 10 min: every window changes by 2 ≥ 1; the last
    // reading alone passes but no W of run follows it.
    EXPECT_TRUE(std::isnan(stabilisedAt({0, 2, 4, 6, 8, 10, 12}, 600, 1)));
    // A plateau (5, 5.2, 5.3, 5.3) then cool-down (3, 1): from 2400 the windows
    // change by 2.3 and 2: a plateau followed by movement is not stabilisation.
    EXPECT_TRUE(std::isnan(stabilisedAt({0, 5, 5.2, 5.3, 5.3, 3, 1}, 600, 1)));
    // Settling in the last W only: 10 → 10.5 from 3000, and 600 s follow: 3000 s.
    EXPECT_EQ(stabilisedAt({0, 2, 4, 6, 8, 10, 10.5}, 600, 1), 3000);
}

// Two targets, both directions, a deviation offset at cycle 0 that the drift removes.
//   100 mm '+' at t = 0, 600, ..., 3600: 1.5 + brief drift → drift 0 .. 8.3,
//     max +8.3 at 3600, stabilised at 2400 (above).
//   100 mm '-' at t = 10, 610, ..., 3610: −2 + (0, −1, −3, −4, −4.5, −4.6, −4.6):
//     Δ per window 1, 2, 1, 0.5, 0.1, 0, 0: 10, 610 and 1210 fail (1 is not
//     below 1), stabilised at 1810; max −4.6 first at 3010.
//   0 mm both ways: deviation 0.4 throughout, drift 0, stabilised at 0.
// Mixing '+' and '-' would average 8.3 and −4.6; the axis figures are the
// '+' maximum and the later of the stabilisation times, 2400.
Run twoDirectionRun() {
    driftlab::Run run;
    run.id = QStringLiteral("M1");
    add(run, 0, kUp, 0, {0.4, 0.4, 0.4, 0.4, 0.4, 0.4, 0.4});
    add(run, 100, kUp, 0, {1.5, 3.5, 6.5, 8.5, 9.5, 9.7, 9.8});
    add(run, 100, kDown, 10, {-2, -3, -5, -6, -6.5, -6.6, -6.6});
    add(run, 0, kDown, 10, {0.4, 0.4, 0.4, 0.4, 0.4, 0.4, 0.4});
    return run;
}

TEST(Iso230_3Golden, movingAxisBothDirectionsKeptApart) {
    const AxisDriftEvaluation e = evaluateAxisDrift(twoDirectionRun(), settings(600, 1));
    ASSERT_TRUE(e.ok()) << qPrintable(e.error);
    ASSERT_EQ(e.targets.size(), 4u);
    EXPECT_EQ(e.cycles, 7);
    EXPECT_EQ(e.zero_mm, 0);
    EXPECT_EQ(e.far_end_mm, 100);
    const TargetDrift* up = e.find(100, kUp);
    const TargetDrift* down = e.find(100, kDown);
    ASSERT_TRUE(up && down);
    EXPECT_EQ(up->cycles, (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
    EXPECT_NEAR(up->drift.drift_um[2], 5, kExactUm);
    EXPECT_NEAR(up->drift.max_drift_um, 8.3, kExactUm);
    EXPECT_EQ(up->drift.max_drift_time_s, 3600);
    EXPECT_EQ(up->drift.stabilised_time_s, 2400);
    EXPECT_NEAR(down->drift.max_drift_um, -4.6, kExactUm);
    EXPECT_EQ(down->drift.max_drift_time_s, 3010);
    EXPECT_NEAR(down->drift.range_um, 4.6, kExactUm);
    EXPECT_EQ(down->drift.stabilised_time_s, 1810);
    const TargetDrift* zero = e.find(0, kDown);
    ASSERT_TRUE(zero);
    EXPECT_EQ(zero->drift.max_drift_um, 0);
    EXPECT_EQ(zero->drift.stabilised_time_s, 10);
    ASSERT_GE(e.max_index, 0);
    EXPECT_EQ(e.targets[std::size_t(e.max_index)].target_mm, 100);
    EXPECT_EQ(e.targets[std::size_t(e.max_index)].direction, kUp);
    EXPECT_NEAR(e.max_drift_um, 8.3, kExactUm);
    EXPECT_EQ(e.stabilised_time_s, 2400);
    EXPECT_TRUE(e.warnings.isEmpty());
}

TEST(Iso230_3Golden, axisNotStabilisedWhenOneTargetIsNot) {
    driftlab::Run run = twoDirectionRun();
    add(run, 200, kUp, 20, {0, 2, 4, 6, 8, 10, 12});  // never settles (above)
    const AxisDriftEvaluation e = evaluateAxisDrift(run, settings(600, 1));
    ASSERT_TRUE(e.ok()) << qPrintable(e.error);
    EXPECT_EQ(e.far_end_mm, 200);
    EXPECT_NEAR(e.max_drift_um, 12, kExactUm);
    EXPECT_TRUE(std::isnan(e.stabilised_time_s));
}

SampleSeries samples(std::vector<QString> columns, std::vector<std::vector<double>> values) {
    SampleSeries s;
    for (std::size_t i = 0; i < values.front().size(); ++i) s.time_s.push_back(300.0 * double(i));
    s.columns = std::move(columns);
    s.values = std::move(values);
    return s;
}

Campaign probeCampaign(RunKind kind, std::vector<Channel> channels, SampleSeries series) {
    Campaign c;
    c.channels = std::move(channels);
    driftlab::Run run;
    run.id = QStringLiteral("SPX");
    run.kind = kind;
    run.samples = std::move(series);
    c.runs.push_back(std::move(run));
    return c;
}

Channel probe(const char* id, ChannelRole role) {
    return {QLatin1String(id), Quantity::Displacement, role, {}, {}, {}};
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Spindle run, samples every 300 s over 0..3600 (13 samples).
//   D_z (drift_z): 10, 9, 8, 7, 6, 5 (t = 0..1500) then 5 to the end: drift
//     0 .. −5, max −5 first at 1500, range 5. W = 600, D = 1: from 1200 the
//     window holds −4, −5, −5 (1 ✗); from 1500 on 0 ✓, 2100 s follow: 1500 s.
//     With D = 1.5: 1200 passes, 900 holds −3 .. −5 (2 ✗): 1200 s.
//   D_y (drift_y): 0 throughout; D_a (tilt_a): 2·t/3600 µm, 0 .. 2.
//     Tilt A = (D_a − D_y) / 100 mm: 2 µm / 100 mm = 20 µrad at 3600 s.
//   D_x (drift_x): 0.5 with one missing cell: drift 0, stabilised at 0.
Campaign spindleCampaign() {
    std::vector<double> z, y, a, x;
    for (int i = 0; i <= 12; ++i) {
        z.push_back(i <= 5 ? 10.0 - i : 5.0);
        y.push_back(0);
        a.push_back(2.0 * 300 * i / 3600);
        x.push_back(i == 4 ? kNaN : 0.5);
    }
    return probeCampaign(
        RunKind::Spindle,
        {probe("D_x", ChannelRole::DriftX),
         probe("D_y", ChannelRole::DriftY),
         probe("D_z", ChannelRole::DriftZ),
         probe("D_a", ChannelRole::TiltA),
         {QStringLiteral("T_spindle"), Quantity::Temperature, ChannelRole::Spindle, {}, {}, {}}},
        samples({"D_x", "D_y", "D_z", "D_a", "T_spindle"}, {x, y, z, a, std::vector(13, 20.0)}));
}

TEST(Iso230_3Golden, spindleProbesLinearThenFlat) {
    const Campaign c = spindleCampaign();
    const ProbeDriftEvaluation e = evaluateProbeDrift(c, c.runs.front(), settings(600, 1));
    ASSERT_TRUE(e.ok()) << qPrintable(e.error);
    ASSERT_EQ(e.probes.size(), 4u);  // the temperature channel is not a probe
    const ProbeDrift& z = e.probes[2];
    EXPECT_EQ(z.channel_id, QStringLiteral("D_z"));
    EXPECT_EQ(z.reference_um, 10);
    EXPECT_EQ(z.drift.max_drift_um, -5);
    EXPECT_EQ(z.drift.max_drift_time_s, 1500);
    EXPECT_EQ(z.drift.range_um, 5);
    EXPECT_EQ(z.drift.stabilised_time_s, 1500);
    EXPECT_EQ(e.probes[0].drift.time_s.size(), 12u);  // the missing cell skipped
    EXPECT_EQ(e.probes[0].drift.stabilised_time_s, 0);
    // D_a: 0.1667 µm per 300 s never varies by 1 in 600 s: stabilised at 0.
    EXPECT_EQ(e.probes[3].drift.stabilised_time_s, 0);
    EXPECT_EQ(e.stabilised_time_s, 1500);
    EXPECT_TRUE(e.tilts.empty());
    EXPECT_TRUE(e.notes.join(' ').contains(QStringLiteral("distance")));

    DriftSettings wider = settings(600, 1.5);
    EXPECT_EQ(evaluateProbeDrift(c, c.runs.front(), wider).probes[2].drift.stabilised_time_s, 1200);
}

TEST(Iso230_3Golden, spindleTiltFromTwoProbesAtAKnownDistance) {
    const Campaign c = spindleCampaign();
    DriftSettings s = settings(600, 1);
    s.probe_distance_mm = 100;
    const ProbeDriftEvaluation e = evaluateProbeDrift(c, c.runs.front(), s);
    ASSERT_TRUE(e.ok()) << qPrintable(e.error);
    ASSERT_EQ(e.tilts.size(), 1u);  // B needs a tilt_b probe, which this run lacks
    EXPECT_EQ(e.tilts[0].name, QStringLiteral("A"));
    EXPECT_EQ(e.tilts[0].from, QStringLiteral("D_y"));
    EXPECT_EQ(e.tilts[0].to, QStringLiteral("D_a"));
    EXPECT_NEAR(e.tilts[0].drift.max_drift_um, 2, kExactUm);
    EXPECT_EQ(e.tilts[0].drift.max_drift_time_s, 3600);
    EXPECT_NEAR(e.tilts[0].max_tilt_urad, 20, kExactUm);
    EXPECT_TRUE(
        e.notes.join(' ').contains(QStringLiteral("tilt B not derived: no probe with "
                                                  "role tilt_b")));
}

// ETVE, one probe (role drift) at 0, 300, 600, 900 s: 1, 3, 0, 2 → drift
// 0, 2, −1, 1: max +2 at 300, range 2 − (−1) = 3; the last window (1 → end)
// has no W after it: not stabilised.
TEST(Iso230_3Golden, etveRangeOverTheRun) {
    const Campaign c = probeCampaign(RunKind::Etve, {probe("D", ChannelRole::Drift)},
                                     samples({"D"}, {{1, 3, 0, 2}}));
    const ProbeDriftEvaluation e = evaluateProbeDrift(c, c.runs.front(), settings(600, 1));
    ASSERT_TRUE(e.ok()) << qPrintable(e.error);
    ASSERT_EQ(e.probes.size(), 1u);
    EXPECT_EQ(e.probes[0].drift.max_drift_um, 2);
    EXPECT_EQ(e.probes[0].drift.max_drift_time_s, 300);
    EXPECT_EQ(e.probes[0].drift.range_um, 3);
    EXPECT_TRUE(std::isnan(e.stabilised_time_s));
    EXPECT_TRUE(e.notes.isEmpty());  // tilts belong to spindle runs
}

TEST(Iso230_3BadInput, noCycleZeroNamesTheRun) {
    driftlab::Run run;
    run.id = QStringLiteral("R7");
    run.positioning.push_back({600, 1, 0, kUp, 1});
    run.positioning.push_back({1200, 2, 0, kUp, 2});
    const AxisDriftEvaluation e = evaluateAxisDrift(run);
    EXPECT_FALSE(e.ok());
    EXPECT_TRUE(e.error.startsWith(QStringLiteral("run R7: no cycle 0"))) << qPrintable(e.error);
    EXPECT_TRUE(e.targets.empty());
}

TEST(Iso230_3BadInput, targetMissingInCycleZeroIsNamed) {
    driftlab::Run run = twoDirectionRun();
    run.positioning.push_back({610, 1, 50, kDown, 1});
    const AxisDriftEvaluation e = evaluateAxisDrift(run);
    EXPECT_EQ(e.error, QStringLiteral("run M1: target 50 mm, direction '-': no reading in "
                                      "cycle 0 (the cold reference)"));
    EXPECT_TRUE(e.targets.empty());
    driftlab::Run twice = twoDirectionRun();
    twice.positioning.push_back({5, 0, 100, kUp, 1.6});
    EXPECT_TRUE(evaluateAxisDrift(twice).error.contains(QStringLiteral("2 readings in cycle 0")));
    driftlab::Run none;
    none.id = QStringLiteral("S9");
    EXPECT_EQ(evaluateAxisDrift(none).error, QStringLiteral("run S9: no positioning readings"));
}

TEST(Iso230_3BadInput, spindleRunWithoutDisplacementChannel) {
    const Campaign c = probeCampaign(
        RunKind::Spindle,
        {{QStringLiteral("T_spindle"), Quantity::Temperature, ChannelRole::Spindle, {}, {}, {}}},
        samples({"T_spindle"}, {{20, 21}}));
    const ProbeDriftEvaluation e = evaluateProbeDrift(c, c.runs.front());
    EXPECT_TRUE(e.error.startsWith(QStringLiteral("run SPX: no displacement channel")))
        << qPrintable(e.error);
}

TEST(Iso230_3BadInput, settingsRefused) {
    QString why;
    EXPECT_TRUE(DriftSettings{}.isValid(&why));
    EXPECT_FALSE(settings(0, 1).isValid(&why));
    EXPECT_TRUE(why.contains(QStringLiteral("window")));
    EXPECT_FALSE(settings(600, -1).isValid(&why));
    DriftSettings s;
    s.probe_distance_mm = 0;
    EXPECT_FALSE(s.isValid(&why));
    EXPECT_TRUE(evaluateAxisDrift(twoDirectionRun(), settings(600, 0))
                    .error.startsWith(QStringLiteral("run M1: stabilisation tolerance")));
}

TEST(Iso230_3Example, movingRunS1AndSpindleRunSP1) {
    const bundle::BundleReadResult read = bundle::readBundle(
        QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/examples/x-axis-moving-state"));
    ASSERT_TRUE(read.ok());
    const Campaign& c = *read.campaign;
    const AxisDriftEvaluation s1 = evaluateAxisDrift(*c.findRun(QStringLiteral("S1")));
    ASSERT_TRUE(s1.ok()) << qPrintable(s1.error);
    EXPECT_EQ(s1.cycles, 7);
    EXPECT_EQ(s1.targets.size(), 22u);  // 11 targets × 2 directions
    EXPECT_EQ(s1.zero_mm, 0);
    EXPECT_EQ(s1.far_end_mm, 700);
    for (Direction d : {kUp, kDown}) {
        const TargetDrift* near = s1.find(0, d);
        const TargetDrift* far = s1.find(700, d);
        ASSERT_TRUE(near && far);
        // The screw grows from its fixed end at −40 mm: the far end drifts more.
        EXPECT_GT(std::abs(far->drift.max_drift_um), std::abs(near->drift.max_drift_um) + 10);
    }
    for (const TargetDrift& t : s1.targets) {
        EXPECT_TRUE(std::isfinite(t.drift.max_drift_um));
        EXPECT_EQ(t.drift.drift_um.front(), 0);
    }
    // Warm-up then cool-down to the end of the run: not stabilised.
    EXPECT_TRUE(std::isnan(s1.stabilised_time_s));

    const driftlab::Run& sp1 = *c.findRun(QStringLiteral("SP1"));
    const ProbeDriftEvaluation p = evaluateProbeDrift(c, sp1);
    ASSERT_TRUE(p.ok()) << qPrintable(p.error);
    ASSERT_EQ(p.probes.size(), 5u);
    EXPECT_EQ(p.probes[2].role, ChannelRole::DriftZ);
    // The z probe sees the spindle grow: the largest drift of the five, negative.
    for (const ProbeDrift& probe : p.probes) {
        EXPECT_TRUE(std::isfinite(probe.drift.max_drift_um));
        EXPECT_GE(std::abs(p.probes[2].drift.max_drift_um), std::abs(probe.drift.max_drift_um));
    }
    EXPECT_LT(p.probes[2].drift.max_drift_um, -10);
    EXPECT_GT(p.probes[2].drift.range_um, 10);
}

}  // namespace
}  // namespace driftlab::iso
