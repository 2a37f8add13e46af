#include "tests/models/SpindleTestCampaigns.h"

#include <cmath>

namespace driftlab::test {

Campaign spindleCampaign(int thermometers, bool speedChannel) {
    std::vector<std::pair<QString, ChannelRole>> temperatures;
    for (int k = 1; k <= thermometers; ++k)
        temperatures.emplace_back(QStringLiteral("T%1").arg(k), ChannelRole::Spindle);
    Campaign c = feedAxisCampaign(temperatures);
    if (speedChannel) {
        c.channels.push_back(
            {QStringLiteral("n_spindle"), Quantity::Speed, ChannelRole::Spindle, {}, {}, {}});
        c.sample_columns.push_back(QStringLiteral("n_spindle"));
    }
    c.channels.push_back(
        {QStringLiteral("D_z"), Quantity::Displacement, ChannelRole::DriftZ, {}, {}, {}});
    c.sample_columns.push_back(QStringLiteral("D_z"));
    return c;
}

void addSpindleRun(Campaign& c, double duration_s, const std::map<QString, Profile>& columns) {
    driftlab::Run run =
        sampledRun(c, QStringLiteral("SP%1").arg(c.runs.size() + 1), duration_s, 15, columns);
    run.kind = RunKind::Spindle;
    c.runs.push_back(run);
}

double responseTo(const Programme& blocks, double (*input)(double rpm), double tau_s, double t) {
    double e = 0, start = 0;
    for (const auto& [rpm, duration_s] : blocks) {
        const double u = input(rpm);
        if (t <= start + duration_s) return u + (e - u) * std::exp(-(t - start) / tau_s);
        e = u + (e - u) * std::exp(-duration_s / tau_s);
        start += duration_s;
    }
    return e;
}

double krpm(double rpm) {
    return rpm / 1000;
}

double krpmSquared(double rpm) {
    return krpm(rpm) * krpm(rpm);
}

double speedAt(const Programme& blocks, double t) {
    double start = 0;
    for (const auto& [rpm, duration_s] : blocks) {
        if (t < start + duration_s) return rpm;
        start += duration_s;
    }
    return 0.0;
}

Campaign rotorCampaign() {
    Campaign c = spindleCampaign(4, true);
    const std::array<Programme, 4> programmes{
        Programme{{6000, 7200}, {0, 3600}},
        Programme{{2000, 3600}, {5000, 3600}, {8000, 3600}},
        Programme{{8000, 3600}, {0, 1800}, {4000, 3600}, {0, 1800}},
        Programme{{3000, 5400}, {9000, 2700}, {0, 2700}},
    };
    for (std::size_t r = 0; r < programmes.size(); ++r) {
        const Programme blocks = programmes[r];
        std::map<QString, Profile> columns;
        auto bearing = [blocks](std::size_t k, double t) {
            return kBearingRise_K_per_krpm[k] * responseTo(blocks, krpm, kBearingLag_s[k], t);
        };
        for (std::size_t k = 0; k < 4; ++k)
            columns[QStringLiteral("T%1").arg(k + 1)] = [=](double t) {
                return 22 + bearing(k, t);
            };
        columns[QStringLiteral("n_spindle")] = [blocks](double t) { return speedAt(blocks, t); };
        columns[QStringLiteral("D_z")] = [=](double t) {
            double drift =
                0.3 + kRotorGain_um_per_krpm2 * responseTo(blocks, krpmSquared, kRotorLag_s, t);
            for (std::size_t k = 0; k < 4; ++k) drift += kBearingGain_um_per_K[k] * bearing(k, t);
            return drift;
        };
        addSpindleRun(c, 10800, columns);
    }
    return c;
}

}  // namespace driftlab::test
