#pragma once
// The decision rule of ISO 14253-1 for an upper tolerance T on a measured
// value y with expanded uncertainty U: conformance is proven only when
// y + U ≤ T, non-conformance only when y − U > T; in between the measurement
// cannot tell, and the verdict says so instead of passing or failing the axis
// on a coin toss (docs/acceptance.md).

#include <QString>

namespace driftlab::iso {

enum class Verdict {
    Pass,           ///< conformance proven: y + U ≤ T
    Fail,           ///< non-conformance proven: y − U > T
    NotProven,      ///< neither: y lies within U of T
    NotDetermined,  ///< the value itself is not determined (NaN)
};

QString toString(Verdict verdict);  // "PASS", "FAIL", "NOT PROVEN", "NOT DETERMINED"

struct Decision {
    QString parameter;
    double value_um = 0;
    double expanded_um = 0;   ///< U
    double tolerance_um = 0;  ///< T
    Verdict verdict = Verdict::NotDetermined;
    /// T − (y + U): how much room conformance has (negative: not proven).
    double margin_um = 0;
};

Decision decide(const QString& parameter, double value_um, double expanded_um, double tolerance_um);

}  // namespace driftlab::iso
