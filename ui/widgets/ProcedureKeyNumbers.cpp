#include "ui/widgets/ProcedureKeyNumbers.h"

#include <QCoreApplication>
#include <cmath>

namespace driftlab::ui {
namespace {

using procedures::Procedure;
using procedures::ProcedureKind;

QString tr(const char* text) {
    return QCoreApplication::translate("ProcedureKeyNumbers", text);
}

/// A number of every moving state; shown is the first state's.
ProcedureKeyNumber everyState(const char* label, const char* key,
                              double procedures::MovingStateStep::*member) {
    return {tr(label), QString::fromLatin1(key), 0,
            [member](const Procedure& p) {
                const auto& states = p.moving_states->states;
                return states.empty() ? 0.0 : states.front().*member;
            },
            [member](Procedure& p, double v) {
                for (auto& state : p.moving_states->states) state.*member = v;
            }};
}

}  // namespace

std::vector<ProcedureKeyNumber> keyNumbersOf(ProcedureKind kind) {
    std::vector<ProcedureKeyNumber> numbers{
        {tr("Sample interval (s)"), QStringLiteral("sample_interval_s"), 1,
         [](const Procedure& p) { return p.sample_interval_s; },
         [](Procedure& p, double v) { p.sample_interval_s = v; }}};
    switch (kind) {
        case ProcedureKind::MovingStates:
            numbers.push_back(everyState("Warm-up of each state (s)", "states[*].warmup_s",
                                         &procedures::MovingStateStep::warmup_s));
            numbers.push_back(everyState("Cool-down of each state (s)", "states[*].cooldown_s",
                                         &procedures::MovingStateStep::cooldown_s));
            numbers.push_back(
                {tr("Targets"), QStringLiteral("moving_states.targets"), 0,
                 [](const Procedure& p) { return double(p.moving_states->targets); },
                 [](Procedure& p, double v) { p.moving_states->targets = int(std::lround(v)); }});
            break;
        case ProcedureKind::Iso230_3Axis:
            numbers.push_back(
                {tr("Longest warm-up (s)"), QStringLiteral("thermal_distortion.max_warmup_s"), 0,
                 [](const Procedure& p) { return p.thermal_distortion->max_warmup_s; },
                 [](Procedure& p, double v) { p.thermal_distortion->max_warmup_s = v; }});
            numbers.push_back(
                {tr("Cool-down (s)"), QStringLiteral("thermal_distortion.cooldown_s"), 0,
                 [](const Procedure& p) { return p.thermal_distortion->cooldown_s; },
                 [](Procedure& p, double v) { p.thermal_distortion->cooldown_s = v; }});
            break;
        case ProcedureKind::Etve:
            numbers.push_back({tr("Duration (s)"), QStringLiteral("etve.duration_s"), 0,
                               [](const Procedure& p) { return p.etve->duration_s; },
                               [](Procedure& p, double v) { p.etve->duration_s = v; }});
            break;
        case ProcedureKind::Iso230_2:
            numbers.push_back(
                {tr("Cycles"), QStringLiteral("positioning.cycles"), 0,
                 [](const Procedure& p) { return double(p.positioning->cycles); },
                 [](Procedure& p, double v) { p.positioning->cycles = int(std::lround(v)); }});
            break;
        case ProcedureKind::Spindle:
            break;
    }
    return numbers;
}

QString readableDuration(double seconds) {
    const long long s = std::llround(seconds);
    if (s < 120) return QStringLiteral("%1 s").arg(s);
    const long long minutes = (s + 30) / 60;
    if (minutes < 60) return QStringLiteral("%1 min").arg(minutes);
    return QStringLiteral("%1 h %2 min")
        .arg(minutes / 60)
        .arg(minutes % 60, 2, 10, QLatin1Char('0'));
}

}  // namespace driftlab::ui
