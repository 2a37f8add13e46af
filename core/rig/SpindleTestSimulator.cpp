#include "core/rig/SpindleTestSimulator.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "core/rig/SensorModel.h"

namespace driftlab::rig {
namespace {

// Housing: fast node heated by bearing friction ∝ n^1.4; column: slow node
// heated by the housing. Time constants and gains chosen to give the tens of µm
// of axial (z) drift typical of a machining-centre spindle at 9000 rpm.
constexpr double kHousingTau_s = 900;
constexpr double kColumnTau_s = 5400;
constexpr double kHousingRiseAt10000rpm_K = 14;
constexpr double kColumnCoupling = 0.45;

double steadyHousingRise(double speed_rpm) {
    return kHousingRiseAt10000rpm_K * std::pow(std::abs(speed_rpm) / 10000.0, 1.4);
}

}  // namespace

std::vector<Channel> spindleTestChannels() {
    auto probe = [](const char* id, ChannelRole role, const char* where) {
        return Channel{QString::fromLatin1(id),
                       Quantity::Displacement,
                       role,
                       QString::fromLatin1(where),
                       {},
                       {}};
    };
    return {
        {QStringLiteral("T_spindle"),
         Quantity::Temperature,
         ChannelRole::Spindle,
         QStringLiteral("spindle housing"),
         {},
         {}},
        {QStringLiteral("S_speed"),
         Quantity::Speed,
         ChannelRole::Spindle,
         QStringLiteral("spindle drive"),
         {},
         {}},
        probe("D_x", ChannelRole::DriftX, "test mandrel, x probe"),
        probe("D_y", ChannelRole::DriftY, "test mandrel, y probe"),
        probe("D_z", ChannelRole::DriftZ, "test mandrel face, z probe"),
        probe("D_a", ChannelRole::TiltA, "test mandrel, second y probe (tilt about x)"),
        probe("D_b", ChannelRole::TiltB, "test mandrel, second x probe (tilt about y)"),
    };
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
    std::normal_distribution<double> probeNoise(0.0, 0.1);
    SensorModel spindleSensor({}, spec.seed + 1);
    SensorModel ambientSensor({}, spec.seed + 2);
    const double nan = std::numeric_limits<double>::quiet_NaN();

    // Which simulated value each sample column carries (-1: not logged in this run).
    const char* ids[] = {"T_spindle", "S_speed", "D_x", "D_y", "D_z", "D_a", "D_b", "T_ambient"};
    std::vector<int> source(sampleColumns.size(), -1);
    for (std::size_t k = 0; k < sampleColumns.size(); ++k)
        for (int i = 0; i < int(std::size(ids)); ++i)
            if (sampleColumns[k] == QLatin1String(ids[i])) source[k] = i;

    // Probes resolve 1 nm.
    auto probe = [&](double drift_um) {
        return std::round((drift_um + probeNoise(rng)) * 1000) / 1000;
    };
    auto ambientAt = [&](double time_s) {
        return spec.ambient_C + spec.ambient_swing_K *
                                    std::sin(2 * std::numbers::pi * time_s / spec.ambient_period_s);
    };
    // housing_K and column_K: rises from the spindle's heat; the *Room_C nodes
    // follow the room. Without a swing the room nodes stay at ambient_C exactly
    // and add exactly 0, so a constant room gives the same numbers as before.
    double housing_K = 0, column_K = 0, t = 0, blockStart = 0;
    double housingRoom_C = spec.ambient_C, columnRoom_C = spec.ambient_C;
    std::size_t block = 0;
    const double dt = spec.sample_interval_s;
    double total_s = 0;
    for (const SpeedBlock& b : spec.blocks) total_s += b.duration_s;
    for (; t <= total_s + 1e-9; t += dt) {
        while (block + 1 < spec.blocks.size() && t >= blockStart + spec.blocks[block].duration_s)
            blockStart += spec.blocks[block++].duration_s;
        const double speed = t < total_s ? spec.blocks[block].speed_rpm : 0;
        if (t > 0) {
            // Exact first-order steps for inputs held over the interval.
            housing_K = steadyHousingRise(speed) +
                        (housing_K - steadyHousingRise(speed)) * std::exp(-dt / kHousingTau_s);
            column_K = kColumnCoupling * housing_K +
                       (column_K - kColumnCoupling * housing_K) * std::exp(-dt / kColumnTau_s);
            // The room over the interval, held at its middle value.
            const double room_C = ambientAt(t - dt / 2);
            housingRoom_C = room_C + (housingRoom_C - room_C) * std::exp(-dt / kHousingTau_s);
            columnRoom_C = room_C + (columnRoom_C - room_C) * std::exp(-dt / kColumnTau_s);
        }
        const double housingTotal_K = housing_K + (housingRoom_C - spec.ambient_C);
        const double columnTotal_K = column_K + (columnRoom_C - spec.ambient_C);
        const double driftZ_um = -(1.6 * housingTotal_K + 2.2 * columnTotal_K);
        const double values[] = {
            spindleSensor.read(spec.ambient_C + housingTotal_K, dt),  // T_spindle
            speed,                                                    // S_speed
            probe(0.15 * housingTotal_K),                             // D_x
            probe(-0.9 * columnTotal_K),                              // D_y
            probe(driftZ_um),                                         // D_z
            probe(-0.35 * columnTotal_K),                             // D_a
            probe(0.05 * housingTotal_K),                             // D_b
            ambientSensor.read(ambientAt(t), dt),                     // T_ambient
        };
        run.samples.time_s.push_back(t);
        for (std::size_t k = 0; k < sampleColumns.size(); ++k)
            run.samples.values[k].push_back(source[k] < 0 ? nan : values[source[k]]);
    }
    return run;
}

}  // namespace driftlab::rig
