#include "tests/models/ModelTestSupport.h"

#include <cmath>
#include <limits>
#include <memory>
#include <random>

namespace driftlab::test {

double warmCool(double time_s, double tau_s, double warmupEnd_s) {
    const double start_s = 60;
    auto rise = [&](double t) { return t <= start_s ? 0.0 : 1 - std::exp(-(t - start_s) / tau_s); };
    if (time_s <= warmupEnd_s) return rise(time_s);
    return rise(warmupEnd_s) * std::exp(-(time_s - warmupEnd_s) / tau_s);
}

double lagOfRise(double s, double tau1_s, double tau2_s) {
    if (s <= 0) return 0;
    return 1 -
           (tau1_s * std::exp(-s / tau1_s) - tau2_s * std::exp(-s / tau2_s)) / (tau1_s - tau2_s);
}

Profile randomWalk(unsigned seed, double step_K, double dt_s, double duration_s) {
    auto walk = std::make_shared<std::vector<double>>();
    std::mt19937 rng(seed);
    std::normal_distribution<double> step(0.0, step_K);
    double value = 20;
    for (double t = 0; t <= duration_s + dt_s; t += dt_s) {
        walk->push_back(value);
        value += step(rng);
    }
    return [walk, dt_s](double time_s) { return (*walk)[std::size_t(std::lround(time_s / dt_s))]; };
}

Campaign feedAxisCampaign(const std::vector<std::pair<QString, ChannelRole>>& temperatures) {
    Campaign c;
    c.name = QStringLiteral("synthetic feed axis");
    c.machine = {
        QStringLiteral("VMC-850"), QStringLiteral("X"), QStringLiteral("generic-modbus"), {}};
    c.screw = Screw{900,     40,   kLeadMm, kFixedEndMm, QStringLiteral("fixed-free"),
                    11.5e-6, 7850, 460,     45,          {}};
    c.nut_length_mm = 80;
    c.travel_mm = RangeMm{0, 700};
    c.interferometer = Interferometer{150, true, {}};
    for (const auto& [id, role] : temperatures) {
        c.channels.push_back({id, Quantity::Temperature, role, {}, {}, {}});
        c.sample_columns.push_back(id);
    }
    c.sample_columns.insert(c.sample_columns.end(), {kPositionColumn, kFeedColumn, kTorqueColumn});
    return c;
}

Run sampledRun(const Campaign& campaign, const QString& id, double duration_s, double step_s,
               const std::map<QString, Profile>& columns) {
    Run run;
    run.id = id;
    run.kind = RunKind::Moving;
    run.samples.columns = campaign.sample_columns;
    run.samples.values.assign(campaign.sample_columns.size(), {});
    const long rows = std::lround(duration_s / step_s);
    for (long i = 0; i <= rows; ++i) {
        const double t = double(i) * step_s;
        run.samples.time_s.push_back(t);
        for (std::size_t c = 0; c < campaign.sample_columns.size(); ++c) {
            const auto profile = columns.find(campaign.sample_columns[c]);
            run.samples.values[c].push_back(profile == columns.end()
                                                ? std::numeric_limits<double>::quiet_NaN()
                                                : profile->second(t));
        }
    }
    return run;
}

std::vector<double> targetsMm() {
    std::vector<double> targets;
    for (int i = 0; i <= 7; ++i) targets.push_back(100.0 * i);
    return targets;
}

void addPositioning(Run& run, double interval_s, double until_s,
                    const std::function<double(double time_s, double x_mm)>& thermalError_um) {
    auto cold = [](double x, Direction d) {
        return 2.0 * std::sin(x / 90.0) + (d == Direction::Negative ? 3.5 : 0.0);
    };
    const long cycles = std::lround(until_s / interval_s);
    for (long k = 0; k <= cycles; ++k) {
        const double t = double(k) * interval_s;
        for (Direction d : {Direction::Positive, Direction::Negative})
            for (double x : targetsMm())
                run.positioning.push_back(
                    {t, int(k), x, d, cold(x, d) + (k == 0 ? 0.0 : thermalError_um(t, x))});
    }
}

Campaign twoSensorCampaign(int runs, const TwoSensorGains& gains,
                           const std::function<double(int run)>& gainScale) {
    Campaign c = feedAxisCampaign({{QStringLiteral("T_nut"), ChannelRole::Nut},
                                   {QStringLiteral("T_bearing"), ChannelRole::Bearing},
                                   {QStringLiteral("T_air"), ChannelRole::Air},
                                   {QStringLiteral("T_bed"), ChannelRole::Structure},
                                   {QStringLiteral("T_motor"), ChannelRole::Motor}});
    const double duration_s = 4 * 3600, step_s = 10, warmupEnd_s = 3 * 3600;
    for (int r = 0; r < runs; ++r) {
        const double nutRise = 5.0 + r, nutTau = 900.0 + 300 * r;
        const double bearingRise = 2.0 + 0.5 * r, bearingTau = 3000.0 + 500 * r;
        const double scale = gainScale ? gainScale(r) : 1.0;
        auto nut = [=](double t) { return nutRise * warmCool(t, nutTau, warmupEnd_s); };
        auto bearing = [=](double t) { return bearingRise * warmCool(t, bearingTau, warmupEnd_s); };
        const unsigned seed = 100u * unsigned(r);
        Run run = sampledRun(
            c, QStringLiteral("S%1").arg(r + 1), duration_s, step_s,
            {{QStringLiteral("T_nut"), [=](double t) { return 20 + nut(t); }},
             {QStringLiteral("T_bearing"), [=](double t) { return 20 + bearing(t); }},
             {QStringLiteral("T_air"), randomWalk(seed + 1, 0.02, step_s, duration_s)},
             {QStringLiteral("T_bed"), randomWalk(seed + 2, 0.02, step_s, duration_s)},
             {QStringLiteral("T_motor"), randomWalk(seed + 3, 0.05, step_s, duration_s)}});
        addPositioning(run, 600, duration_s, [=](double t, double x) {
            const double dx = x - kFixedEndMm;
            return scale *
                   (nut(t) * (gains.a1 + gains.b1 * dx) + bearing(t) * (gains.a2 + gains.b2 * dx));
        });
        c.runs.push_back(std::move(run));
    }
    return c;
}

}  // namespace driftlab::test
