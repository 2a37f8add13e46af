#include "core/compensation/LiveThermalCompensation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace driftlab::compensation {
namespace {

/// Moves `applied` toward `target` by at most `limit`; true when held back.
bool approach(double& applied, double target, double limit) {
    const double change = target - applied;
    if (std::abs(change) <= limit) {
        applied = target;
        return false;
    }
    applied += std::copysign(limit, change);
    return true;
}

}  // namespace

bool LiveSettings::isValid(QString* why) const {
    auto fail = [why](const QString& message) {
        if (why) *why = message;
        return false;
    };
    if (!(update_interval_s > 0) || !std::isfinite(update_interval_s))
        return fail(
            QStringLiteral("update interval %1 s is not a positive time").arg(update_interval_s));
    if (!(max_change_um > 0))
        return fail(
            QStringLiteral("change limit %1 µm per update is not positive").arg(max_change_um));
    if (!std::isfinite(offset_position_mm))
        return fail(QStringLiteral("the offset position is not a number"));
    for (std::size_t i = 0; i < table_positions_mm.size(); ++i) {
        if (!std::isfinite(table_positions_mm[i]))
            return fail(QStringLiteral("table position %1 is not a number").arg(i));
        if (i > 0 && table_positions_mm[i] <= table_positions_mm[i - 1])
            return fail(QStringLiteral("table positions must increase: point %1 (%2 mm) is not "
                                       "beyond point %3 (%4 mm)")
                            .arg(i)
                            .arg(table_positions_mm[i])
                            .arg(i - 1)
                            .arg(table_positions_mm[i - 1]));
    }
    return true;
}

LiveThermalCompensation::LiveThermalCompensation(const physics::ScrewThermalParameters& parameters,
                                                 double initial_C, LiveSettings settings)
    : model_(parameters, initial_C), settings_(std::move(settings)) {
    QString why;
    if (!settings_.isValid(&why)) throw std::invalid_argument(why.toStdString());
    positions_mm_ = settings_.table_positions_mm;
    positions_mm_.push_back(settings_.offset_position_mm);
    applied_.table_correction_um.assign(settings_.table_positions_mm.size(), 0.0);
    nextDue_s_ = settings_.update_interval_s;
}

double LiveThermalCompensation::targetOffsetUm() const {
    return -model_.thermalError_um(std::vector<double>{settings_.offset_position_mm}).front();
}

std::optional<LiveUpdate> LiveThermalCompensation::step(const physics::StepConditions& conditions,
                                                        MachineState state) {
    model_.step(conditions);
    const double now_s = model_.time_s();
    // Small tolerance: steps that land on the interval by float sums count as on it.
    if (!pendingSince_s_ && now_s >= nextDue_s_ - 1e-9) pendingSince_s_ = nextDue_s_;
    if (!pendingSince_s_ || !isSafeToCompensate(state)) return std::nullopt;
    applied_ = makeUpdate(*pendingSince_s_);
    pendingSince_s_.reset();
    // The schedule stays on whole intervals; the ones that passed during a
    // wait for a safe state are covered by this update, not replayed.
    while (nextDue_s_ <= now_s + 1e-9) nextDue_s_ += settings_.update_interval_s;
    return applied_;
}

LiveUpdate LiveThermalCompensation::makeUpdate(double due_s) {
    // One O(cells) pass for every position (ScrewThermalModel's prefix sum).
    const std::vector<double> error_um = model_.thermalError_um(positions_mm_);
    LiveUpdate next = applied_;
    next.time_s = model_.time_s();
    next.due_s = due_s;
    next.limited = false;
    const double limit = settings_.max_change_um;
    for (std::size_t i = 0; i < next.table_correction_um.size(); ++i)
        next.limited |= approach(next.table_correction_um[i], -error_um[i], limit);
    next.limited |= approach(next.offset_um, -error_um.back(), limit);
    return next;
}

}  // namespace driftlab::compensation
