#pragma once
// One run's ISO 230-3 drift, whichever kind of run it is, and its JSON as
// `driftlab-cli iso230-3 --json` prints it: the CLI and the GUI's ISO 230-3
// page evaluate and show the same figures (docs/iso230-3.md).

#include <QJsonObject>
#include <optional>

#include "core/iso/DriftAcceptance.h"
#include "core/iso/Iso230_3.h"

namespace driftlab::iso {

/// A feed-axis run with positioning readings: drift per target and direction.
bool hasAxisDrift(const Run& run);
/// A spindle or ETVE run: drift per probe.
bool hasProbeDrift(const Run& run);

/// The evaluation of one run: `axis` for a run with axis drift, else `probes`.
struct RunDrift {
    QString error;  ///< empty on success; names the run
    std::optional<AxisDriftEvaluation> axis;
    std::optional<ProbeDriftEvaluation> probes;

    bool ok() const { return error.isEmpty(); }
    QStringList warnings() const;
    /// What an acceptance specification's drift tolerances are checked against.
    DriftFigures figures() const;
};

/// Evaluates `run` of `campaign`; an error when it has neither axis nor probe drift.
RunDrift evaluateRunDrift(const Campaign& campaign, const Run& run, const DriftSettings& settings);

/// A difference of readings given to 0.01 µm prints as 11.069999999999999:
/// rounded to 1 pm, far below any probe's or interferometer's resolution.
double picometres(double value_um);

/// The run's object of `iso230-3 --json` "runs" without "run", "kind" and
/// "acceptance" (the caller adds those). Requires drift.ok().
QJsonObject runDriftJson(const RunDrift& drift);

}  // namespace driftlab::iso
