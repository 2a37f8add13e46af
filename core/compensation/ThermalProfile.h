#pragma once
// The thermal part of a compensation table: a model fitted on training runs,
// evaluated at a stated state (a run and a time in it) over the axis. Two
// steps, so that the caller can vet the fit (no harm, gaps) before it is
// used: fitThermalState, then thermalProfile. Shared by `driftlab-cli
// compensate` (table = cold error + this), the straight-line temperature
// compensation formats and the GUI. Faults are ServiceErrors.

#include <QStringList>
#include <functional>
#include <memory>
#include <vector>

#include "core/compensation/CompensationTable.h"
#include "core/compensation/TemperatureCompensationLine.h"
#include "core/domain/Campaign.h"
#include "core/domain/ServiceError.h"
#include "core/models/DataGaps.h"
#include "core/models/ModelValidation.h"
#include "core/models/ThermalErrorModel.h"

namespace driftlab::compensation {

struct ThermalStateOptions {
    QString model;           ///< a model family, or "auto"
    QStringList train_runs;  ///< the runs it is fitted on (not state_run)
    QString state_run;       ///< the thermal state: a run …
    double time_s = 0;       ///< … and a time in it
    /// Told `what` is being done ("fitting heat-transfer") at 0 and at 1.
    std::function<void(const QString& what, double fraction)> progress;
    /// Asked inside the fit; true stops it (ServiceError).
    std::function<bool()> cancelled;
};

/// The model fitted for a thermal state, not yet evaluated.
struct ThermalStateFit {
    std::shared_ptr<const models::ThermalErrorModel> model;
    QStringList notes;                  ///< the fit's notes
    models::Validation validation;      ///< the model's cross-validation on its training runs
    std::vector<models::DataGap> gaps;  ///< of the training runs and the state's run
    std::vector<models::RunData> training;
    models::RunData state;
    QStringList train_runs;
    QString state_run;
    double time_s = 0;
    /// `auto` chose no compensation: why (the table would carry no thermal
    /// part); empty otherwise.
    QString choseNone() const;
};

/// The first feed-axis run with positioning readings that is not
/// `state_run`: the default training run; empty when there is none.
QString defaultTrainingRun(const Campaign& campaign, const QString& state_run);

/// Fits and validates the model for the state. Throws ServiceError:
/// BadRequest when the state's run ends before time_s ("run S3 ends at …"),
/// Failed when the data or the fit fail or when cancelled.
ThermalStateFit fitThermalState(const Campaign& campaign, const ThermalStateOptions& options);

struct ThermalProfile {
    ErrorProfile error_um;  ///< actual − target, µm, at a position
    /// The 95 % half-width of the model's prediction interval, µm, at a position.
    ErrorProfile uncertainty_um;
    models::Validation validation;  ///< the model's cross-validation on its training runs
    QString description;            ///< "heat-transfer fitted on S1, at S3 t = 3600 s"
    double from_mm = 0, to_mm = 0;  ///< where it was evaluated
    double fixed_end_mm = 0;        ///< the screw's fixed end (0 without a screw)
};

/// The fitted model's thermal error at the state over [from_mm, to_mm].
/// Throws ServiceError with the model's reason when it cannot predict there.
ThermalProfile thermalProfile(const ThermalStateFit& fit, double from_mm, double to_mm);

/// The least-squares line of the profile over its range, about reference_mm:
/// what the straight-line temperature compensation formats carry.
ErrorLine thermalErrorLine(const ThermalProfile& profile, double reference_mm);

}  // namespace driftlab::compensation
