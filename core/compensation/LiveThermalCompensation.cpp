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
    : m_model(parameters, initial_C), m_settings(std::move(settings)) {
    QString why;
    if (!m_settings.isValid(&why)) throw std::invalid_argument(why.toStdString());
    m_positions_mm = m_settings.table_positions_mm;
    m_positions_mm.push_back(m_settings.offset_position_mm);
    m_applied.table_correction_um.assign(m_settings.table_positions_mm.size(), 0.0);
    m_nextDue_s = m_settings.update_interval_s;
}

double LiveThermalCompensation::targetOffsetUm() const {
    return -m_model.thermalError_um(std::vector<double>{m_settings.offset_position_mm}).front();
}

std::optional<LiveUpdate> LiveThermalCompensation::step(const physics::StepConditions& conditions,
                                                        MachineState state) {
    m_model.step(conditions);
    const double now_s = m_model.time_s();
    // Small tolerance: steps that land on the interval by float sums count as on it.
    if (!m_pendingSince_s && now_s >= m_nextDue_s - 1e-9) m_pendingSince_s = m_nextDue_s;
    if (!m_pendingSince_s || !isSafeToCompensate(state)) return std::nullopt;
    m_applied = makeUpdate(*m_pendingSince_s);
    m_pendingSince_s.reset();
    // The schedule stays on whole intervals; the ones that passed during a
    // wait for a safe state are covered by this update, not replayed.
    while (m_nextDue_s <= now_s + 1e-9) m_nextDue_s += m_settings.update_interval_s;
    return m_applied;
}

LiveUpdate LiveThermalCompensation::makeUpdate(double due_s) {
    // One O(cells) pass for every position (ScrewThermalModel's prefix sum).
    const std::vector<double> error_um = m_model.thermalError_um(m_positions_mm);
    LiveUpdate next = m_applied;
    next.time_s = m_model.time_s();
    next.due_s = due_s;
    next.limited = false;
    const double limit = m_settings.max_change_um;
    for (std::size_t i = 0; i < next.table_correction_um.size(); ++i)
        next.limited |= approach(next.table_correction_um[i], -error_um[i], limit);
    next.target_offset_um = -error_um.back();
    next.limited |= approach(next.offset_um, next.target_offset_um, limit);
    return next;
}

}  // namespace driftlab::compensation
