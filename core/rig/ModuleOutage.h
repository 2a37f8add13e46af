#pragma once
// The simulated rig's temperature module not answering for a span of a run
// (RigSpec::module_outages): its columns are missing there, as a lost real
// module leaves them (acquisition/engine/DeviceRunSource); the controller's
// columns and the interferometer readings go on. `simulate` and the engine's
// simulated rig blank the same rows, so a campaign logged live is still the
// campaign simulated in one go.

#include <QString>
#include <optional>
#include <vector>

#include "core/domain/Campaign.h"
#include "core/rig/RigSpec.h"
#include "core/rig/SimulatedAxisRun.h"

namespace driftlab::rig {

/// `RUN@FROM-TO`, FROM and TO in seconds of run time (e.g. S3@3000-3300);
/// nullopt with `error` saying what is wrong (the form, or FROM ≥ TO).
std::optional<ModuleOutage> parseModuleOutage(const QString& text, QString* error);

/// The outages of run `run_id`, sorted by start, overlapping ones merged.
std::vector<ModuleOutage> outagesOf(const std::vector<ModuleOutage>& outages,
                                    const QString& run_id);

/// Whether the module answers at run time `t_s`, given its run's outages.
bool moduleAnswers(const std::vector<ModuleOutage>& runOutages, double t_s);

/// The columns the temperature module serves: those of the channels that
/// measure a temperature, as indices into `columns`.
std::vector<std::size_t> temperatureColumns(const std::vector<Channel>& channels,
                                            const std::vector<QString>& columns);

/// Blanks (NaN) the `temperature` columns of the samples inside an outage.
void blankOutages(const std::vector<ModuleOutage>& runOutages,
                  const std::vector<std::size_t>& temperature, SampleSeries& samples);
/// The same for row-major rows of `out`, from row `firstRow` on.
void blankOutages(const std::vector<ModuleOutage>& runOutages,
                  const std::vector<std::size_t>& temperature, std::size_t width, RunOutput& out,
                  std::size_t firstRow);

}  // namespace driftlab::rig
