#pragma once
// Clean data of the simulated rig (one moving-state run, the real
// CampaignSimulator) and helpers to inject a sensor fault into a copy.

#include <QString>
#include <vector>

#include "core/domain/Campaign.h"
#include "core/sensors/SensorHealth.h"

namespace driftlab::sensors::test {

/// S1 of the simulated rig, 1 h warm-up and 30 min cool-down, sampled every
/// 10 s; simulated once per test binary.
const Campaign& cleanCampaign();
const Run& cleanRun();

std::vector<double>& columnOf(SampleSeries& series, const QString& id);
const std::vector<double>& columnOf(const SampleSeries& series, const QString& id);
/// First row at or after `time_s`.
std::size_t rowAt(const SampleSeries& series, double time_s);

/// Indices of the rows whose flags contain `fault`.
std::vector<std::size_t> rowsWith(const std::vector<SensorFlags>& flags, SensorFault fault);
/// Indices of the rows with any flag.
std::vector<std::size_t> flaggedRows(const std::vector<SensorFlags>& flags);
std::vector<std::size_t> indexRange(std::size_t first, std::size_t last);

}  // namespace driftlab::sensors::test
