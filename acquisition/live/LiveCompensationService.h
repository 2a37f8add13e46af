#pragma once
// Live thermal compensation as a service (docs/live-compensation.md): the
// heat-transfer model, or an adopted extension of it, fitted on training
// runs, a stored run replayed as live data through it, and each update it
// applies (only between cuts, limited per update) reported and, with a
// controller, written to its live-offset registers (LiveOffsetWriter).
// `driftlab-cli live` and the GUI's Live compensation page call the same two
// steps: planLive, then runLive.
// Faults are ServiceErrors naming where and why.

#include <QStringList>
#include <functional>
#include <optional>
#include <vector>

#include "acquisition/modbus/ModbusUrl.h"
#include "core/compensation/LiveReplay.h"
#include "core/domain/Campaign.h"
#include "core/domain/ServiceError.h"
#include "core/models/DataGaps.h"
#include "core/models/ModelValidation.h"

namespace driftlab::live {

/// The controller could not be opened: the ServiceError of its connection.
struct ControllerError : ServiceError {
    using ServiceError::ServiceError;
};

/// When the replayed machine cuts, from_s < t <= to_s.
struct CuttingWindow {
    double from_s = 0, to_s = 0;
};

struct LiveCompensationOptions {
    QString run;             ///< the run replayed as live data
    QStringList train_runs;  ///< the model's training runs (not `run`)
    /// "heat-transfer", or an adopted extension of it ("heat-transfer+motor_heat")
    /// whose causes act on the screw's heat flow.
    QString model = QStringLiteral("heat-transfer");
    double update_interval_s = 60;
    double max_change_um = 5;  ///< largest change of any value per update
    int table_points = 128;    ///< 2…1024, over the run's measured targets
    /// Where the single live offset is evaluated; default the targets' middle.
    std::optional<double> offset_position_mm;
    /// Without a controller: when the machine cuts (default: it never does).
    std::vector<CuttingWindow> cutting;
    /// Written to, and asked for the machine state, at every update.
    std::optional<modbus::ModbusUrl> controller;
    int stale_after_s = 600;  ///< the controller's live_timeout_s
    double speedup = 0;       ///< replay N times faster than logged; 0: as fast as possible
    /// Send a model that does worse than no compensation (no harm) anyway.
    bool override_no_harm = false;

    /// Told `what` is being done ("fitting heat-transfer") at 0 and at 1.
    std::function<void(const QString& what, double fraction)> progress;
    /// Asked inside the fit and at every model step; true stops the work.
    std::function<bool()> cancelled;
    /// Every update applied, after the controller took it.
    std::function<void(const compensation::LiveUpdate&)> on_update;
    /// The cut gate: the machine state whenever it changes (first at the first step).
    std::function<void(double time_s, MachineState state)> on_state;
};

/// The fitted model and the replay set up: what runLive steps.
struct LivePlan {
    QString run;
    QStringList train_runs;
    QString model_name;                 ///< as in the options
    models::Validation validation;      ///< the model's cross-validation on its training runs
    std::vector<models::DataGap> gaps;  ///< of the training and replayed runs
    models::RunData replayed;
    physics::ScrewThermalParameters screw;
    /// What an extension does to the logged inputs online (empty for most).
    std::function<void(models::ScrewRunInputs&)> online_inputs;
    compensation::LiveSettings settings;
    /// The 95 % half-width of the prediction at the offset position (NaN: not known).
    double uncertainty_um = 0;

    /// "the heat-transfer+motor_heat model fitted on S1,S2".
    QString model() const;
    /// Empty, or why the model must not be sent to a machine (no harm).
    QString harmReason() const { return validation.harmReason(model()); }
};

/// Fits the model on the training runs and sets up the replay of the run.
/// Throws ServiceError: BadRequest for runs that overlap, a model that is
/// not heat-transfer or an extension of it, or settings out of range;
/// Failed when the data or the fit fail or are cancelled.
LivePlan planLive(const Campaign& campaign, const LiveCompensationOptions& options);

struct LiveRunResult {
    compensation::LiveReplayResult replay;
    int written = 0;           ///< updates the controller took
    QString controller;        ///< its URL, empty without one
    QString controller_error;  ///< set: the controller failed and the replay stopped
    double reduction() const {
        return replay.rms_before_um > 0 ? 1 - replay.rms_after_um / replay.rms_before_um : 0;
    }
};

/// Replays the plan's run, writing each update to the controller when one
/// is given. Refuses (ServiceError, BadRequest) to write a model worse than
/// no compensation without override_no_harm, throws ControllerError when
/// the controller cannot be opened and ServiceError when the replay fails. A controller that
/// stops answering ends the replay with controller_error set: nothing more
/// is written.
LiveRunResult runLive(const LivePlan& plan, const LiveCompensationOptions& options);

}  // namespace driftlab::live
