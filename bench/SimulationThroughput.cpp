#include "bench/SimulationThroughput.h"

#include <algorithm>
#include <chrono>

#include "core/domain/Median.h"
#include "core/physics/ScrewThermalModel.h"

namespace driftlab::bench {

BenchmarkCampaign::BenchmarkCampaign() {
    parameters.cells = kCells;
    const double from = 210, to = 490, feed = 8000, block = 600, dwell = 100;
    double t = 0;
    double at = from;
    bool up = true;
    while (t < kDuration_s) {
        const double blockEnd = std::min(kDuration_s, t + block);
        while (t < blockEnd) {
            const double target = up ? to : from;
            const double full_s = std::abs(target - at) / feed * 60;
            if (t + full_s <= blockEnd) {
                motion.push_back({t, t + full_s, at, target, up ? feed : -feed});
                t += full_s;
                at = target;
                up = !up;
            } else {  // the block ends mid-stroke; the next one carries on
                const double reached = at + (target - at) * (blockEnd - t) / full_s;
                motion.push_back({t, blockEnd, at, reached, up ? feed : -feed});
                t = blockEnd;
                at = reached;
            }
        }
        const double pause = std::min(dwell, kDuration_s - t);
        if (pause <= 0) break;
        motion.push_back({t, t + pause, at, at, 0});
        t += pause;
    }
}

double BenchmarkCampaign::run() const {
    physics::ScrewThermalModel model(parameters, 20);
    physics::StepConditions c;
    c.dt_s = kStep_s;
    c.motion = motion;
    const long n = steps();
    for (long i = 0; i < n; ++i) {
        c.ambient_begin_C = 20 + 2 * static_cast<double>(i) / static_cast<double>(n);
        c.ambient_end_C = 20 + 2 * static_cast<double>(i + 1) / static_cast<double>(n);
        model.step(c);
    }
    return model.thermalError_um(parameters.fixed_end_axis_mm + parameters.length_m * 1e3);
}

SimulationThroughput measureSimulationThroughput(int repetitions) {
    repetitions = std::max(1, repetitions);
    const BenchmarkCampaign campaign;
    std::vector<double> ms;
    volatile double sink = 0;
    for (int r = 0; r < repetitions; ++r) {
        const auto start = std::chrono::steady_clock::now();
        sink = sink + campaign.run();
        const auto stop = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
    }
    SimulationThroughput result;
    result.repetitions = repetitions;
    result.campaign_ms = median(ms);
    result.cell_steps_per_s = campaign.cellSteps() / (result.campaign_ms * 1e-3);
    return result;
}

}  // namespace driftlab::bench
