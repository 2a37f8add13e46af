#include "SensorHealthTestSupport.h"

#include <stdexcept>

#include "core/rig/CampaignSimulator.h"

namespace driftlab::sensors::test {

const Campaign& cleanCampaign() {
    static const Campaign campaign = [] {
        rig::RigSpec spec;
        rig::MovingStateRun run = rig::defaultMovingStates().front();
        run.warmup_s = 3600;
        run.cooldown_s = 1800;
        spec.runs = {run};
        return rig::simulateCampaign(spec);
    }();
    return campaign;
}

const Run& cleanRun() {
    return cleanCampaign().runs.front();
}

std::vector<double>& columnOf(SampleSeries& series, const QString& id) {
    const int index = series.columnIndex(id);
    if (index < 0) throw std::invalid_argument(id.toStdString());
    return series.values[static_cast<std::size_t>(index)];
}

const std::vector<double>& columnOf(const SampleSeries& series, const QString& id) {
    return columnOf(const_cast<SampleSeries&>(series), id);
}

std::size_t rowAt(const SampleSeries& series, double time_s) {
    std::size_t row = 0;
    while (row < series.rowCount() && series.time_s[row] < time_s) ++row;
    return row;
}

std::vector<std::size_t> rowsWith(const std::vector<SensorFlags>& flags, SensorFault fault) {
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < flags.size(); ++i)
        if (has(flags[i], fault)) rows.push_back(i);
    return rows;
}

std::vector<std::size_t> flaggedRows(const std::vector<SensorFlags>& flags) {
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < flags.size(); ++i)
        if (flags[i] != kNoFlags) rows.push_back(i);
    return rows;
}

std::vector<std::size_t> indexRange(std::size_t first, std::size_t last) {
    std::vector<std::size_t> rows;
    for (std::size_t i = first; i <= last; ++i) rows.push_back(i);
    return rows;
}

}  // namespace driftlab::sensors::test
