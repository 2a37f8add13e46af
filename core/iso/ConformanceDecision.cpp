#include "core/iso/ConformanceDecision.h"

#include <cmath>
#include <limits>

namespace driftlab::iso {

QString toString(Verdict verdict) {
    switch (verdict) {
        case Verdict::Pass:
            return QStringLiteral("PASS");
        case Verdict::Fail:
            return QStringLiteral("FAIL");
        case Verdict::NotProven:
            return QStringLiteral("NOT PROVEN");
        case Verdict::NotDetermined:
            return QStringLiteral("NOT DETERMINED");
    }
    return {};
}

Decision decide(const QString& parameter, double value_um, double expanded_um,
                double tolerance_um) {
    Decision d{parameter, value_um, expanded_um, tolerance_um, Verdict::NotDetermined, 0};
    if (!std::isfinite(value_um) || !std::isfinite(expanded_um)) {
        d.margin_um = std::numeric_limits<double>::quiet_NaN();
        return d;
    }
    d.margin_um = tolerance_um - (value_um + expanded_um);
    // The boundaries belong to the zone they close: y + U = T is proven
    // conformance, y − U = T not yet proven non-conformance.
    if (value_um + expanded_um <= tolerance_um)
        d.verdict = Verdict::Pass;
    else if (value_um - expanded_um > tolerance_um)
        d.verdict = Verdict::Fail;
    else
        d.verdict = Verdict::NotProven;
    return d;
}

}  // namespace driftlab::iso
