#include "core/compensation/LeadAliasing.h"

#include <cmath>

namespace driftlab::compensation {

QString leadAliasingWarning(const std::vector<double>& targets_mm, double lead_mm) {
    if (!(lead_mm > 0) || targets_mm.size() < 3) return {};
    for (double target : targets_mm) {
        const double leads = (target - targets_mm.front()) / lead_mm;
        if (std::abs(leads - std::round(leads)) * lead_mm > kLeadPhaseToleranceMm) return {};
    }
    const double phase_mm = std::fmod(std::fmod(targets_mm.front(), lead_mm) + lead_mm, lead_mm);
    return QStringLiteral(
               "the %1 measured targets (%2 to %3 mm) all lie %4 mm past a multiple of the "
               "%5 mm screw lead: the screw's periodic error is sampled at one phase and "
               "aliased into the table; ISO 230-2 asks for irregularly spaced targets")
        .arg(targets_mm.size())
        .arg(targets_mm.front(), 0, 'f', 3)
        .arg(targets_mm.back(), 0, 'f', 3)
        .arg(phase_mm < kLeadPhaseToleranceMm || lead_mm - phase_mm < kLeadPhaseToleranceMm
                 ? 0.0
                 : phase_mm,
             0, 'f', 3)
        .arg(lead_mm, 0, 'f', 3);
}

}  // namespace driftlab::compensation
