#include "core/compensation/LiveReplay.h"

#include <algorithm>
#include <cmath>

#include "core/domain/HeldLinear.h"
#include "core/models/ModelError.h"

namespace driftlab::compensation {
namespace {

/// The applied table's correction at a position, linear between points and
/// held at the ends; the single offset when there is no table.
double correctionAt(const LiveUpdate& applied, const std::vector<double>& positions_mm,
                    double x_mm) {
    if (positions_mm.empty()) return applied.offset_um;
    return heldLinearAt(positions_mm, applied.table_correction_um, x_mm);
}

}  // namespace

MachineState stateFromMotion(const std::vector<MotionSegment>& motion, double time_s) {
    for (const MotionSegment& s : motion)
        if (time_s >= s.start_s && time_s < s.end_s && !s.isDwell()) return MachineState::Moving;
    return MachineState::Idle;
}

LiveReplayResult replayLive(const models::RunData& run,
                            const physics::ScrewThermalParameters& parameters,
                            LiveReplayOptions options) {
    LiveReplayResult result;
    try {
        models::ScrewRunInputs in =
            models::prepareScrewRun(run, options.dt_s, QStringLiteral("live compensation"));
        if (options.online_inputs) options.online_inputs(in);
        LiveThermalCompensation live(parameters, in.initial_C, options.settings);
        std::vector<models::ErrorObservation> readings = run.observations;
        std::sort(readings.begin(), readings.end(),
                  [](const auto& a, const auto& b) { return a.time_s < b.time_s; });
        std::size_t next = 0;
        double before = 0, after = 0, afterOffset = 0;
        // A reading taken during a step sees the correction applied before it.
        auto score = [&](double until_s) {
            for (; next < readings.size() && readings[next].time_s <= until_s; ++next) {
                const auto& r = readings[next];
                const double left =
                    r.error_um + correctionAt(live.applied(), options.settings.table_positions_mm,
                                              r.position_mm);
                const double leftOffset = r.error_um + live.applied().offset_um;
                before += r.error_um * r.error_um;
                after += left * left;
                afterOffset += leftOffset * leftOffset;
            }
        };
        physics::StepConditions step;
        step.motion = in.motion;
        step.dt_s = in.dt_s;
        for (std::size_t k = 1; k < in.ambient_C.size(); ++k) {
            if (options.cancelled && options.cancelled()) {
                result.cancelled = true;
                break;
            }
            score(double(k - 1) * in.dt_s + 1e-9);
            step.ambient_begin_C = in.ambient_C[k - 1];
            step.ambient_end_C = in.ambient_C[k];
            step.mean_torque_squared_Nm2 =
                in.mean_torque_squared_Nm2.empty() ? 0.0 : in.mean_torque_squared_Nm2[k - 1];
            const double end_s = double(k) * in.dt_s;
            const MachineState state =
                options.state_at ? options.state_at(end_s) : stateFromMotion(in.motion, end_s);
            if (auto update = live.step(step, state)) {
                result.updates.push_back(*update);
                if (options.on_update && !options.on_update(*update)) {
                    result.cancelled = true;
                    break;
                }
            }
        }
        score(INFINITY);
        result.readings = next;
        if (next > 0) {
            result.rms_before_um = std::sqrt(before / double(next));
            result.rms_after_um = std::sqrt(after / double(next));
            result.rms_after_offset_um = std::sqrt(afterOffset / double(next));
        }
    } catch (const models::ModelError& e) {
        result.error = e.message;
    } catch (const std::invalid_argument& e) {
        result.error = QString::fromStdString(e.what());
    }
    return result;
}

}  // namespace driftlab::compensation
