#include "core/rig/SpindleTestSimulator.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "core/rig/SensorModel.h"
#include "core/rig/SpindleThermalNetwork.h"

namespace driftlab::rig {
namespace {

/// The drift probes' view of the head and column rises (K): the shaft carries
/// the tool, the column core sets where the head sits.
struct DriftGains {
    double shaft, housing, columnSkin, columnCore;
};
constexpr DriftGains kDriftX{0.3, 0.1, 0, 0};
constexpr DriftGains kDriftY{0, 0, -0.3, -2.0};
constexpr DriftGains kDriftZ{-3.0, -0.6, 0, -5.0};
constexpr DriftGains kTiltA{0, 0, 0, -0.35};
constexpr DriftGains kTiltB{0.05, 0.05, 0, 0};

/// The sensors' thermal contact: a real sensor screwed onto a casting lags it.
constexpr double kSensorLag_s = 30;

}  // namespace

std::vector<Channel> spindleTestChannels() {
    auto channel = [](const char* id, Quantity quantity, ChannelRole role, const char* where) {
        return Channel{QString::fromLatin1(id), quantity, role, QString::fromUtf8(where), {}, {}};
    };
    auto temperature = [&](const char* id, ChannelRole role, const char* where) {
        return channel(id, Quantity::Temperature, role, where);
    };
    auto probe = [&](const char* id, ChannelRole role, const char* where) {
        return channel(id, Quantity::Displacement, role, where);
    };
    return {
        temperature("T_spindle", ChannelRole::Spindle, "spindle housing, front"),
        channel("S_speed", Quantity::Speed, ChannelRole::Spindle, "spindle drive"),
        probe("D_x", ChannelRole::DriftX, "test mandrel, x probe"),
        probe("D_y", ChannelRole::DriftY, "test mandrel, y probe"),
        probe("D_z", ChannelRole::DriftZ, "test mandrel face, z probe"),
        probe("D_a", ChannelRole::TiltA, "test mandrel, second y probe (tilt about x)"),
        probe("D_b", ChannelRole::TiltB, "test mandrel, second x probe (tilt about y)"),
        temperature("T_spindle_bearing", ChannelRole::Spindle, "front bearing seat"),
        temperature("T_spindle_motor", ChannelRole::Spindle, "spindle motor stator"),
        temperature("T_headstock", ChannelRole::Spindle, "headstock, rear"),
        temperature("T_column", ChannelRole::Other, "column surface beside the headstock"),
    };
}

SpindleTestSpec spindleTestProgramme(int index) {
    SpindleTestSpec spec;
    spec.run_id = QStringLiteral("SP%1").arg(index);
    spec.seed = unsigned(index);
    switch (index) {
        case 1:  // the default: three speeds with a stop between
            break;
        case 2:  // fast first, then down
            spec.blocks = {{2400, 9000}, {1800, 4500}, {1800, 0}, {1800, 6000}, {2400, 0}};
            break;
        case 3:  // short cycles, as a job shop runs
            spec.blocks.clear();
            for (int k = 0; k < 6; ++k) spec.blocks.push_back({600, k % 2 ? 0.0 : 8000.0});
            spec.blocks.push_back({3600, 0});
            break;
        case 4:  // a ramp of speeds
            spec.blocks = {{1200, 2000}, {1200, 4000}, {1200, 6000}, {1200, 8000}, {3600, 0}};
            break;
        case 5:
            spec.blocks = {{3600, 6000}, {1200, 0}, {1200, 9000}, {3600, 0}};
            break;
        default: {  // a speed spectrum: blocks of random speed and length
            std::mt19937 rng(unsigned(index) * 7919u);
            std::uniform_int_distribution<int> minutes(10, 20), speed(0, 9);
            spec.blocks.clear();
            for (double total_s = 0; total_s < 9000;) {
                spec.blocks.push_back({60.0 * minutes(rng), 1000.0 * speed(rng)});
                total_s += spec.blocks.back().duration_s;
            }
            spec.blocks.push_back({3600, 0});
        }
    }
    return spec;
}

Run simulateSpindleTest(const SpindleTestSpec& spec, const std::vector<QString>& sampleColumns) {
    Run run;
    run.id = spec.run_id;
    run.kind = spec.kind;
    run.description =
        spec.kind == RunKind::Etve
            ? QStringLiteral("ETVE: machine at rest while the room varies, five drift probes")
            : QStringLiteral("ISO 230-3 spindle test: speed blocks with stops, five drift probes");
    run.samples.columns = sampleColumns;
    run.samples.values.assign(sampleColumns.size(), {});

    std::mt19937_64 rng(spec.seed);
    std::normal_distribution<double> standardNormal;
    const double nan = std::numeric_limits<double>::quiet_NaN();

    // What each sample column carries; the sensors in the order of `ids`.
    const char* ids[] = {"T_spindle",
                         "S_speed",
                         "D_x",
                         "D_y",
                         "D_z",
                         "D_a",
                         "D_b",
                         "T_ambient",
                         "T_spindle_bearing",
                         "T_spindle_motor",
                         "T_headstock",
                         "T_column"};
    std::vector<int> source(sampleColumns.size(), -1);
    for (std::size_t k = 0; k < sampleColumns.size(); ++k)
        for (int i = 0; i < int(std::size(ids)); ++i)
            if (sampleColumns[k] == QLatin1String(ids[i])) source[k] = i;
    std::vector<SensorModel> sensors;
    for (unsigned k = 0; k < 6; ++k)
        sensors.emplace_back(SensorSpec{kSensorLag_s}, spec.seed + 1 + k);

    // Probes resolve 1 nm.
    auto probe = [&](double drift_um) {
        return std::round((drift_um + spec.probe_noise_um * standardNormal(rng)) * 1000) / 1000;
    };
    auto ambientAt = [&](double time_s) {
        return spec.ambient_C + spec.ambient_swing_K *
                                    std::sin(2 * std::numbers::pi * time_s / spec.ambient_period_s);
    };
    const double dt = spec.sample_interval_s;
    SpindleThermalNetwork head(spec.ambient_C, dt);
    auto rise = [&](SpindleNode node) { return head.temperature_C(node) - spec.ambient_C; };
    auto drift = [&](const DriftGains& g) {
        return g.shaft * rise(SpindleNode::Shaft) + g.housing * rise(SpindleNode::Housing) +
               g.columnSkin * rise(SpindleNode::ColumnSkin) +
               g.columnCore * rise(SpindleNode::ColumnCore);
    };

    std::size_t block = 0;
    double total_s = 0, blockStart = 0;
    for (const SpeedBlock& b : spec.blocks) total_s += b.duration_s;
    for (double t = 0; t <= total_s + 1e-9; t += dt) {
        while (block + 1 < spec.blocks.size() && t >= blockStart + spec.blocks[block].duration_s)
            blockStart += spec.blocks[block++].duration_s;
        const double speed = t < total_s ? spec.blocks[block].speed_rpm : 0;
        // The speed of the interval just ended and the room at its middle.
        if (t > 0) head.step(speed, ambientAt(t - dt / 2));
        auto sensor = [&](int k, SpindleNode node) {
            return sensors[std::size_t(k)].read(head.temperature_C(node), dt);
        };
        const double values[] = {
            sensor(0, SpindleNode::Housing),       // T_spindle
            speed,                                 // S_speed
            probe(drift(kDriftX)),                 // D_x
            probe(drift(kDriftY)),                 // D_y
            probe(drift(kDriftZ)),                 // D_z
            probe(drift(kTiltA)),                  // D_a
            probe(drift(kTiltB)),                  // D_b
            sensors[1].read(ambientAt(t), dt),     // T_ambient
            sensor(2, SpindleNode::FrontBearing),  // T_spindle_bearing
            sensor(3, SpindleNode::Motor),         // T_spindle_motor
            sensor(4, SpindleNode::Headstock),     // T_headstock
            sensor(5, SpindleNode::ColumnSkin),    // T_column
        };
        run.samples.time_s.push_back(t);
        for (std::size_t k = 0; k < sampleColumns.size(); ++k)
            run.samples.values[k].push_back(source[k] < 0 ? nan : values[source[k]]);
    }
    return run;
}

}  // namespace driftlab::rig
