#pragma once
// Turns the readings of an interferometer software's CSV export into an
// ISO 230-2 positioning run of a new campaign: each reading gets its target,
// its direction of approach and its cycle, which such exports carry in no
// common form (docs/interferometer.md, "From readings to a positioning run").
//
// Targets are given or inferred: the commanded positions (position less
// deviation) clustered within the tolerance, each cluster's mean to the µm,
// kept when it has readings in every cycle. The direction follows the
// sequence of targets as a linear ISO 230-2 cycle runs it: towards a higher
// target '+', a lower one '-', the same target again the reversal at the end
// of a pass; the first reading takes the direction towards the next target.
// A cycle ends when the direction returns to the first reading's. What
// cannot be assigned is refused, naming the CSV line: nothing is guessed.

#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "core/bundle/BundleError.h"
#include "core/domain/Campaign.h"
#include "core/interferometer/InterferometerSession.h"

namespace driftlab::interferometer {

struct PositioningRunContext {
    QString fileName;  ///< the CSV's, for errors
    QString campaignName;
    QString machine;
    QString axis;
    QString runId = QStringLiteral("P1");
    std::vector<double> targets_mm;  ///< empty: inferred from the readings
    double targetTolerance_mm = 0.5;
    /// A positioning run is a feed-axis run: the bundle format wants the screw
    /// and the nut with it (docs/bundles.md).
    std::optional<Screw> screw;
    std::optional<double> nut_length_mm;
    bool environmentCompensation = true;  ///< the interferometer compensated itself
};

struct PositioningRunBuild {
    std::optional<Campaign> campaign;
    std::optional<bundle::BundleError> error;  ///< names the CSV line of the reading
};

/// The targets of `readings` (sorted): commanded positions clustered within
/// `tolerance_mm`; all clusters, before the every-cycle rule.
std::vector<double> clusterTargets(const std::vector<CorrectedReading>& readings,
                                   double tolerance_mm);

/// A campaign with one positioning run holding every reading, or the first
/// reading that cannot be assigned.
PositioningRunBuild buildPositioningCampaign(const std::vector<CorrectedReading>& readings,
                                             const PositioningRunContext& context);

}  // namespace driftlab::interferometer
