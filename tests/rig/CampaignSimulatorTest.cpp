// The simulated rig writes whole campaigns: realistic magnitudes, a valid
// bundle, every hidden effect visible where physics puts it, a module outage
// only where it is, clear errors.
#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <cmath>
#include <map>

#include "core/bundle/BundleReader.h"
#include "core/bundle/BundleWriter.h"
#include "core/rig/CampaignSimulator.h"
#include "core/rig/ModuleOutage.h"

using namespace driftlab;
using namespace driftlab::rig;

namespace {

RigSpec shortSpec(std::vector<QString> runIds = {QStringLiteral("S1")}) {
    RigSpec spec;
    std::vector<MovingStateRun> runs;
    for (const auto& r : defaultMovingStates())
        if (std::find(runIds.begin(), runIds.end(), r.id) != runIds.end()) runs.push_back(r);
    spec.runs = runs;
    return spec;
}

/// Thermal error of every reading: deviation minus cycle 0 at the same target and direction.
std::map<std::pair<int, double>, double> thermalErrorByCycleAndTarget(const driftlab::Run& run) {
    std::map<std::pair<double, int>, double> cold;
    for (const auto& p : run.positioning)
        if (p.cycle == 0) cold[{p.target_mm, static_cast<int>(p.direction)}] = p.deviation_um;
    std::map<std::pair<int, double>, double> error;
    for (const auto& p : run.positioning)
        if (p.direction == Direction::Positive)
            error[{p.cycle, p.target_mm}] =
                p.deviation_um - cold.at({p.target_mm, static_cast<int>(p.direction)});
    return error;
}

double columnMean(const driftlab::Run& run, const QString& column, double from_s, double to_s) {
    const auto& values =
        run.samples.values[static_cast<std::size_t>(run.samples.columnIndex(column))];
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; i < run.samples.time_s.size(); ++i)
        if (run.samples.time_s[i] >= from_s && run.samples.time_s[i] <= to_s &&
            std::isfinite(values[i])) {
            sum += values[i];
            ++n;
        }
    return sum / n;
}

/// The last warm-up cycle (the reading right after 2 h).
int lastWarmupCycle(const driftlab::Run& run) {
    int cycle = 0;
    for (const auto& p : run.positioning)
        if (p.time_s <= 7200 + 200) cycle = std::max(cycle, p.cycle);
    return cycle;
}

}  // namespace

TEST(CampaignSimulator, fiveMovingStatesGiveThePublishedMagnitudesAndAValidBundle) {
    RigSpec spec;
    spec.spindle_runs = 1;
    const Campaign campaign = simulateCampaign(spec);
    ASSERT_EQ(campaign.runs.size(), 6u);

    for (const driftlab::Run& run : campaign.runs) {
        if (run.kind != RunKind::Moving) continue;
        SCOPED_TRACE(run.id.toStdString());
        const auto error = thermalErrorByCycleAndTarget(run);
        const int cycle = lastWarmupCycle(run);
        const double farEnd = error.at({cycle, 695.0});
        // Published feed-axis tests: tens of µm at the far end after 2 h
        // (60–100 µm for fast or long strokes).
        EXPECT_GT(farEnd, 30.0);
        EXPECT_LT(farEnd, 130.0);
        // The error grows along the axis from the fixed end.
        EXPECT_LT(error.at({cycle, 5.0}), 0.3 * farEnd);
        // Nut and bearings rise several kelvin; the room does not.
        const double nutRise = columnMean(run, QStringLiteral("T_nut"), 7000, 7200) -
                               columnMean(run, QStringLiteral("T_nut"), 0, 0);
        const double bearingRise = columnMean(run, QStringLiteral("T_bearing_fixed"), 7000, 7200) -
                                   columnMean(run, QStringLiteral("T_bearing_fixed"), 0, 0);
        EXPECT_GT(nutRise, 3.0);
        EXPECT_LT(nutRise, 20.0);
        EXPECT_GT(bearingRise, 2.0);
        EXPECT_LT(bearingRise, 20.0);
        EXPECT_LT(std::abs(columnMean(run, QStringLiteral("T_ambient"), 7000, 7200) -
                           columnMean(run, QStringLiteral("T_ambient"), 0, 0)),
                  1.2);
        // Cool-down: the error falls back.
        const int lastCycle = run.positioning.back().cycle;
        EXPECT_LT(error.at({lastCycle, 695.0}), 0.6 * farEnd);
    }
    // S3 (15000 mm/min) heats more than S2 (6500) over the same range.
    const auto s2 = thermalErrorByCycleAndTarget(*campaign.findRun(QStringLiteral("S2")));
    const auto s3 = thermalErrorByCycleAndTarget(*campaign.findRun(QStringLiteral("S3")));
    EXPECT_GT(s3.at({12, 695.0}), 1.5 * s2.at({12, 695.0}));

    QTemporaryDir dir;
    ASSERT_FALSE(bundle::writeBundle(campaign, dir.path()).has_value());
    const bundle::BundleReadResult back = bundle::readBundle(dir.path());
    ASSERT_TRUE(back.ok()) << qPrintable(back.error->toString());
    EXPECT_EQ(*back.campaign, campaign);
}

TEST(CampaignSimulator, theSameSeedGivesTheSameCampaignAndAnotherSeedDoesNot) {
    const Campaign a = simulateCampaign(shortSpec());
    const Campaign b = simulateCampaign(shortSpec());
    RigSpec other = shortSpec();
    other.seed = 2;
    EXPECT_EQ(a, b);
    EXPECT_NE(a.runs[0].samples, simulateCampaign(other).runs[0].samples);
}

TEST(CampaignSimulator, sensorOffsetAndLagChangeOnlyTheirChannel) {
    const Campaign base = simulateCampaign(shortSpec());
    RigSpec spec = shortSpec();
    spec.effects.sensor_offset_K[QStringLiteral("T_bearing_free")] = 0.4;
    spec.effects.sensor_lag_s[QStringLiteral("T_nut")] = 600;
    const Campaign hidden = simulateCampaign(spec);
    const driftlab::Run& r0 = base.runs[0];
    const driftlab::Run& r1 = hidden.runs[0];
    auto mean = [](const driftlab::Run& r, const char* c, double a, double b) {
        return columnMean(r, QString::fromLatin1(c), a, b);
    };
    // Same noise stream: the offset shows whole, within quantisation.
    EXPECT_NEAR(mean(r1, "T_bearing_free", 0, 11000) - mean(r0, "T_bearing_free", 0, 11000), 0.4,
                0.01);
    // A lagged sensor reads low while the screw warms and high while it cools.
    EXPECT_LT(mean(r1, "T_nut", 1000, 7000), mean(r0, "T_nut", 1000, 7000) - 0.5);
    EXPECT_GT(mean(r1, "T_nut", 8000, 11000), mean(r0, "T_nut", 8000, 11000) + 0.3);
    EXPECT_NEAR(mean(r1, "T_bearing_fixed", 0, 11000), mean(r0, "T_bearing_fixed", 0, 11000), 1e-9);
    EXPECT_EQ(r1.positioning, r0.positioning);
}

TEST(CampaignSimulator, interferometerEffectsFollowAirAndStructureTemperatures) {
    const Campaign base = simulateCampaign(shortSpec());
    RigSpec air = shortSpec();
    air.effects.air_refraction = 1;
    RigSpec frame = shortSpec();
    frame.effects.frame_growth_um_per_K = 5;
    const driftlab::Run& r0 = base.runs[0];
    const Campaign airCampaign = simulateCampaign(air);
    const Campaign frameCampaign = simulateCampaign(frame);
    const driftlab::Run& ra = airCampaign.runs[0];
    const driftlab::Run& rf = frameCampaign.runs[0];
    ASSERT_EQ(ra.positioning.size(), r0.positioning.size());
    const double air0 = columnMean(r0, QStringLiteral("T_air"), 0, 0);
    const double bed0 = columnMean(r0, QStringLiteral("T_bed"), 0, 0);
    const double dead = 150;
    int checked = 0;
    for (std::size_t i = 0; i < r0.positioning.size(); ++i) {
        const auto& p = r0.positioning[i];
        if (p.cycle != 12) continue;
        const double dAir =
            columnMean(r0, QStringLiteral("T_air"), p.time_s - 10, p.time_s + 10) - air0;
        const double dBed =
            columnMean(r0, QStringLiteral("T_bed"), p.time_s - 10, p.time_s + 10) - bed0;
        // Edlén: −0.95 ppm/K over the whole beam path (target + dead path).
        const double edlen_um = -0.95e-3 * dAir * (p.target_mm + dead);
        EXPECT_NEAR(ra.positioning[i].deviation_um - p.deviation_um, edlen_um,
                    0.1 + 0.1 * std::abs(edlen_um));
        // The structure shifts the axis zero: the same at every target.
        EXPECT_NEAR(rf.positioning[i].deviation_um - p.deviation_um, 5 * dBed,
                    0.15 + 0.1 * 5 * dBed);
        ++checked;
    }
    EXPECT_EQ(checked, 22);
    EXPECT_GT(columnMean(r0, QStringLiteral("T_air"), 7000, 7200) - air0, 0.5);
}

TEST(CampaignSimulator, heatEffectsChangeTheThermalErrorTheWayPhysicsSays) {
    const std::vector<QString> runs{QStringLiteral("S2"), QStringLiteral("S3")};
    const Campaign base = simulateCampaign(shortSpec(runs));
    auto farEnd = [](const Campaign& c, int run) {
        const auto& r = c.runs[static_cast<std::size_t>(run)];
        return thermalErrorByCycleAndTarget(r).at({lastWarmupCycle(r), 695.0});
    };
    RigSpec forced = shortSpec(runs);
    forced.effects.forced_convection_h1 = 0.15;
    const Campaign cooled = simulateCampaign(forced);
    EXPECT_LT(farEnd(cooled, 1), 0.85 * farEnd(base, 1));

    // n > 1 with equal power at 800 rpm: less heat at 650 rpm, more at 1500 rpm.
    RigSpec exponent = shortSpec(runs);
    exponent.effects.nut_heat_exponent = 1.6;
    const Campaign steep = simulateCampaign(exponent);
    EXPECT_LT(farEnd(steep, 0), farEnd(base, 0));
    EXPECT_GT(farEnd(steep, 1), 1.2 * farEnd(base, 1));

    RigSpec motor = shortSpec(runs);
    motor.effects.motor_heat_W_per_Nm2 = 1.0;
    const Campaign motorHeated = simulateCampaign(motor);
    const driftlab::Run& m = motorHeated.runs[1];
    const driftlab::Run& b = base.runs[1];
    EXPECT_GT(columnMean(m, QStringLiteral("T_bearing_fixed"), 6000, 7200),
              columnMean(b, QStringLiteral("T_bearing_fixed"), 6000, 7200) + 0.5);
}

TEST(CampaignSimulator, channelNamesDropoutsAndTorqueAreLikeARealLog) {
    RigSpec spec = shortSpec();
    spec.names.nut = QStringLiteral("Kanal_7");
    spec.names.structure = QStringLiteral("Bett");
    spec.dropout_probability = 0.01;
    spec.effects.sensor_offset_K[QStringLiteral("Kanal_7")] = 0.2;
    const Campaign c = simulateCampaign(spec);
    ASSERT_NE(c.findChannel(QStringLiteral("Kanal_7")), nullptr);
    EXPECT_EQ(c.findChannel(QStringLiteral("Kanal_7"))->role, ChannelRole::Nut);
    EXPECT_EQ(c.findChannel(QStringLiteral("Bett"))->role, ChannelRole::Structure);
    EXPECT_EQ(c.findChannel(QStringLiteral("T_nut")), nullptr);
    const driftlab::Run& run = c.runs[0];
    std::size_t missing = 0;
    for (const auto& v :
         run.samples
             .values[static_cast<std::size_t>(run.samples.columnIndex(QStringLiteral("Kanal_7")))])
        missing += std::isnan(v);
    EXPECT_GT(missing, 0u);
    EXPECT_LT(missing, run.samples.rowCount() / 20);
    // Torque, the RMS over each 10 s interval: Coulomb + viscous while
    // traversing at 8000 mm/min (1.435 N·m) and J·Δω/t_acc = 5.24 N·m for
    // 80 ms at every reversal (every 2.1 s): sqrt(1.435² + 5.24²·0.08/2.1) = 1.76.
    const auto& torque =
        run.samples.values[static_cast<std::size_t>(run.samples.columnIndex(kTorqueColumn))];
    const auto& feed =
        run.samples.values[static_cast<std::size_t>(run.samples.columnIndex(kFeedColumn))];
    int traversing = 0;
    for (std::size_t i = 0; i < torque.size(); ++i)
        if (std::abs(feed[i]) == 8000 && std::abs(torque[i] - 1.76) < 0.15) ++traversing;
    EXPECT_GT(traversing, 100);
}

TEST(CampaignSimulator, specsThatCannotRunAreRefusedWithTheReason) {
    auto refused = [](const RigSpec& spec, const char* expected) {
        try {
            simulateCampaign(spec);
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
            return;
        }
        ADD_FAILURE() << "accepted a spec that should be refused: " << expected;
    };
    RigSpec s = shortSpec();
    s.screw.diameter_m = -0.04;
    refused(s, "diameter_m");
    s = shortSpec();
    s.screw.length_m = 0;
    refused(s, "length_m");
    s = shortSpec();
    s.physics_step_s = 0;
    refused(s, "physics step");
    s = shortSpec();
    s.runs[0].range_mm = {500, 800};
    refused(s, "outside the travel");
    s = shortSpec();
    s.travel_mm = {0, 1000};
    refused(s, "not on the screw");
    s = shortSpec();
    s.effects.sensor_lag_s[QStringLiteral("T_spindle_nose")] = 100;
    refused(s, "no temperature channel 'T_spindle_nose'");
    s = shortSpec();
    s.runs.push_back(s.runs[0]);
    refused(s, "used twice");
    s = shortSpec();
    s.module_outages = {{QStringLiteral("S3"), 100, 200}};
    refused(s, "module outage in run 'S3', which the rig does not run");
    s = shortSpec();
    s.module_outages = {{QStringLiteral("S1"), 200, 200}};
    refused(s, "end after it starts");
}

TEST(CampaignSimulator, aModuleOutageEmptiesTheTemperatureColumnsOfItsSpanAndNothingElse) {
    RigSpec spec = shortSpec({QStringLiteral("S1"), QStringLiteral("S3")});
    spec.spindle_runs = 1;
    const Campaign without = simulateCampaign(spec);
    spec.module_outages = {{QStringLiteral("S3"), 2800, 3100}, {QStringLiteral("SP1"), 600, 900}};
    const Campaign with = simulateCampaign(spec);
    ASSERT_EQ(with.runs.size(), 3u);
    const auto temperature = temperatureColumns(with.channels, with.sample_columns);
    EXPECT_EQ(temperature.size(), 11u);  // six rig channels, five spindle ones
    for (std::size_t r = 0; r < with.runs.size(); ++r) {
        const driftlab::Run& a = with.runs[r];
        const driftlab::Run& b = without.runs[r];
        SCOPED_TRACE(a.id.toStdString());
        EXPECT_EQ(a.positioning, b.positioning);
        ASSERT_EQ(a.samples.time_s, b.samples.time_s);
        const auto outages = outagesOf(spec.module_outages, a.id);
        std::size_t blanked = 0;
        for (std::size_t c = 0; c < a.samples.columns.size(); ++c) {
            const bool isTemperature =
                std::find(temperature.begin(), temperature.end(), c) != temperature.end();
            for (std::size_t i = 0; i < a.samples.rowCount(); ++i) {
                const double t = a.samples.time_s[i], got = a.samples.values[c][i];
                const double was = b.samples.values[c][i];
                if (isTemperature && !moduleAnswers(outages, t)) {
                    EXPECT_TRUE(std::isnan(got)) << a.samples.columns[c].toStdString() << " " << t;
                    blanked += !std::isnan(was);
                } else if (!(std::isnan(got) && std::isnan(was))) {
                    ASSERT_EQ(got, was) << a.samples.columns[c].toStdString() << " " << t;
                }
            }
        }
        // S3: six channels over 2800…3090 s at 10 s; SP1: its five sensors and the
        // room over 600…895 s at 5 s (its speed and drift probes go on).
        const std::size_t expected = a.id == QLatin1String("S3")    ? 6 * 30
                                     : a.id == QLatin1String("SP1") ? 6 * 60
                                                                    : 0;
        EXPECT_EQ(blanked, expected);
    }
}

TEST(CampaignSimulator, cancellingStopsTheSimulation) {
    SimulationCallbacks callbacks;
    double last = 0;
    callbacks.progress = [&](double f) {
        last = f;
        return f < 0.3;
    };
    EXPECT_THROW(simulateCampaign(shortSpec(), callbacks), SimulationCancelled);
    EXPECT_GE(last, 0.3);
    EXPECT_LT(last, 0.5);
}
