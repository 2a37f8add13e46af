#pragma once
// An ISO 230-2 acceptance of one positioning run as a calibration lab signs
// it: the readings at 20 °C, the test's environment, the evaluation, the
// uncertainty of each value and, where the specification sets a tolerance,
// the verdict by ISO 14253-1's decision rule (docs/acceptance.md).

#include <QString>
#include <QStringList>
#include <vector>

#include "core/domain/Campaign.h"
#include "core/iso/AcceptanceSpecification.h"
#include "core/iso/ConformanceDecision.h"
#include "core/iso/Iso230_2.h"
#include "core/iso/MeasurementUncertainty.h"
#include "core/iso/ReferenceTemperature.h"

namespace driftlab::iso {

struct PositioningAcceptance {
    QString error;  ///< empty on success; names the run or the setting at fault
    QString run_id;
    QString axis;
    TestEnvironment environment;
    Normalisation normalisation;
    std::vector<Reading> readings;  ///< at 20 °C, as normalisation says
    Evaluation evaluation;          ///< of `readings`
    UncertaintyBudget budget;
    std::vector<Decision> decisions;  ///< one per toleranced value, in parameter order
    QStringList notes;

    bool ok() const { return error.isEmpty(); }
    /// FAIL if any value fails, NOT PROVEN if any is not proven, PASS when all
    /// pass; NOT DETERMINED without a tolerance.
    Verdict overall() const;
};

/// Environmental variation error from an ETVE run (machine at rest): the
/// largest range of the axis's drift probe over any window as long as the
/// positioning test, `duration_s` (the whole run if shorter). The probe of
/// role drift_x/drift_y/drift_z matching `axis`, else `drift`, else the
/// largest of them. `error` when the run has no drift probe.
std::optional<double> environmentalVariationError(const Campaign& campaign, const Run& etve,
                                                  const QString& axis, double duration_s,
                                                  QString* source, QString* error);

PositioningAcceptance evaluateAcceptance(const Campaign& campaign, const Run& run,
                                         const AcceptanceSpecification& specification,
                                         const Settings& settings = {});

}  // namespace driftlab::iso
