#pragma once
// Which runs of a campaign an ISO 230-2 evaluation or a compensation table
// can be made from: those with positioning readings. Shared by the CLI's
// --run default and the GUI's run choosers.

#include <QStringList>

#include "core/domain/Campaign.h"

namespace driftlab::iso {

/// The runs with positioning readings, in campaign order.
QStringList runsWithPositioning(const Campaign& campaign);

/// The run to use when none is named: the only positioning run (kind
/// Positioning) with readings, else the only run with readings.
struct DefaultRun {
    QString id;           ///< empty when there is no single candidate
    QStringList choices;  ///< the candidates when there are several
    QString why;          ///< why id is empty
};
DefaultRun defaultPositioningRun(const Campaign& campaign);

/// The run whose positioning readings `iso230-2`, `compensate` and the machine
/// history evaluate: `wanted` (--run), else the default run above.
struct PositioningRunChoice {
    const Run* run = nullptr;  ///< null when there is no such run; `error` says why
    QString error;
    /// The error is the caller's to fix (a --run naming no run, several
    /// candidates to choose from) rather than the campaign's lack of readings.
    bool usage = false;
};
PositioningRunChoice choosePositioningRun(const Campaign& campaign, const QString& wanted);

}  // namespace driftlab::iso
