#include "acquisition/live/LiveCompensationService.h"

#include <QElapsedTimer>
#include <QThread>
#include <algorithm>
#include <cmath>
#include <memory>

#include "acquisition/live/LiveOffsetWriter.h"
#include "core/diagnosis/ExtendedHeatTransferModel.h"
#include "core/models/HeatTransferModel.h"
#include "core/models/ThermalErrorData.h"

namespace driftlab::live {
namespace {

const QString kBaseModel = QStringLiteral("heat-transfer");

bool isCancelled(const LiveCompensationOptions& options) {
    return options.cancelled && options.cancelled();
}

/// Waits until `t_s` of the run is due at `speedup` times the logged pace,
/// in short slices so that a cancel is seen at once.
void paceTo(double t_s, const LiveCompensationOptions& options, const QElapsedTimer& wall) {
    if (!(options.speedup > 0)) return;
    const qint64 due_ms = qint64(t_s * 1000 / options.speedup);
    while (due_ms > wall.elapsed() && !isCancelled(options))
        QThread::msleep(quint64(std::min<qint64>(due_ms - wall.elapsed(), 50)));
}

/// heat-transfer (no `causes`) or its extension by `causes`, fitted and
/// cross-validated on `runs`.
models::ValidatedFit fitModel(const QStringList& causes, const std::vector<models::RunData>& runs,
                              const std::function<bool()>& cancelled) {
    if (causes.isEmpty()) return models::fitValidated(kBaseModel, runs, cancelled);
    return models::fitValidated(
        [causes] { return std::make_unique<diagnosis::ExtendedHeatTransferModel>(causes); }, runs,
        cancelled);
}

}  // namespace

QString LivePlan::model() const {
    return QStringLiteral("the %1 model fitted on %2")
        .arg(model_name, train_runs.join(QLatin1Char(',')));
}

LivePlan planLive(const Campaign& campaign, const LiveCompensationOptions& options) {
    using Kind = ServiceError::Kind;
    if (options.train_runs.isEmpty())
        throw ServiceError(QStringLiteral("live compensation needs a training run"),
                           Kind::BadRequest);
    if (options.train_runs.contains(options.run))
        throw ServiceError(
            QStringLiteral("run %1 is replayed and cannot also be a training run").arg(options.run),
            Kind::BadRequest);
    if (options.table_points < 2 || options.table_points > 1024)
        throw ServiceError(
            QStringLiteral("the live table has %1 points, not 2 to 1024").arg(options.table_points),
            Kind::BadRequest);
    QStringList causes;
    if (options.model != kBaseModel) {
        QString why;
        causes = diagnosis::ExtendedHeatTransferModel::causesOf(options.model, &why);
        if (causes.isEmpty())
            throw ServiceError(
                QStringLiteral("live compensation steps heat-transfer or an extension of it: %1")
                    .arg(why),
                Kind::BadRequest);
    }
    LivePlan plan;
    plan.run = options.run;
    plan.train_runs = options.train_runs;
    plan.model_name = options.model;
    plan.settings.update_interval_s = options.update_interval_s;
    plan.settings.max_change_um = options.max_change_um;
    QString why;
    if (!plan.settings.isValid(&why)) throw ServiceError(why, Kind::BadRequest);

    models::DatasetResult data =
        models::buildDataset(campaign, options.train_runs + QStringList{options.run});
    if (!data.ok()) throw ServiceError(data.error);
    plan.replayed = data.runs.back();
    data.runs.pop_back();
    const QString label = QStringLiteral("fitting ") + options.model;
    if (options.progress) options.progress(label, 0);
    const models::ValidatedFit fitted = fitModel(causes, data.runs, options.cancelled);
    if (isCancelled(options)) throw ServiceError(QStringLiteral("the fit was cancelled"));
    if (options.progress) options.progress(label, 1);
    if (!fitted.fit.success) throw ServiceError(fitted.fit.message);
    plan.validation = fitted.validation;
    plan.gaps = models::gapsOf(data.runs);
    plan.gaps.insert(plan.gaps.end(), plan.replayed.gaps.begin(), plan.replayed.gaps.end());
    const auto& model = static_cast<const models::HeatTransferModel&>(*fitted.model);
    const auto screw = model.fittedScrew(plan.replayed, &why);
    if (!screw) throw ServiceError(why);
    plan.screw = *screw;
    if (const auto& inputs = model.variant().inputs)
        plan.online_inputs = [inputs, values = model.values()](models::ScrewRunInputs& in) {
            inputs(values.data(), in);
        };

    // The table spans the run's measured targets, where its score can be checked.
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& o : plan.replayed.observations) {
        lo = std::min(lo, o.position_mm);
        hi = std::max(hi, o.position_mm);
    }
    if (!(hi > lo))
        throw ServiceError(QStringLiteral("run %1 has no span of targets").arg(options.run));
    const int points = options.table_points;
    for (int i = 0; i < points; ++i)
        plan.settings.table_positions_mm.push_back(lo + (hi - lo) * i / (points - 1));
    plan.settings.offset_position_mm = options.offset_position_mm.value_or((lo + hi) / 2);

    const models::PredictionInterval& band = plan.validation.interval;
    plan.uncertainty_um = band.known()
                              ? band.halfWidthAt(plan.settings.offset_position_mm,
                                                 models::beyondTraining(data.runs, plan.replayed))
                              : NAN;
    return plan;
}

LiveRunResult runLive(const LivePlan& plan, const LiveCompensationOptions& options) {
    LiveRunResult result;
    std::unique_ptr<LiveOffsetWriter> controller;
    if (options.controller) {
        // A rehearsal may show a model that would do harm; a controller may not get it.
        if (plan.validation.worseThanNone() && !options.override_no_harm)
            throw ServiceError(plan.harmReason() + QStringLiteral(": refused, not sent"),
                               ServiceError::Kind::BadRequest);
        controller =
            std::make_unique<LiveOffsetWriter>(*options.controller, 2.0, options.stale_after_s);
        QString error;
        if (!controller->open(&error)) throw ControllerError(error);
        result.controller = controller->url().toString();
    }
    QElapsedTimer wall;
    wall.start();
    std::optional<MachineState> lastState;
    compensation::LiveReplayOptions replay;
    replay.settings = plan.settings;
    replay.cancelled = options.cancelled;
    replay.online_inputs = plan.online_inputs;
    replay.state_at = [&](double t_s) {
        paceTo(t_s, options, wall);
        MachineState state = compensation::stateFromMotion(plan.replayed.motion, t_s);
        if (controller && result.controller_error.isEmpty()) {
            // A controller that stops answering is read as cutting: nothing
            // is applied, and the replay stops at the next update.
            state =
                controller->machineState(&result.controller_error).value_or(MachineState::Cutting);
        } else {
            for (const CuttingWindow& w : options.cutting)
                if (t_s > w.from_s && t_s <= w.to_s) state = MachineState::Cutting;
        }
        if (options.on_state && state != lastState) options.on_state(t_s, state);
        lastState = state;
        return state;
    };
    replay.on_update = [&](const compensation::LiveUpdate& u) {
        if (controller) {
            if (!result.controller_error.isEmpty() ||
                !controller->publish(u.offset_um, true, &result.controller_error))
                return false;
            ++result.written;
        }
        if (options.on_update) options.on_update(u);
        return true;
    };
    result.replay = compensation::replayLive(plan.replayed, plan.screw, replay);
    if (!result.replay.ok()) throw ServiceError(result.replay.error);
    return result;
}

}  // namespace driftlab::live
