#pragma once
// Every candidate's figures in a diagnosis, one indented line each: printed by
// the hidden-effect suites so that a wrong verdict shows why.
#include <QString>

#include "core/diagnosis/Diagnosis.h"

namespace driftlab::test {

inline QString findingsText(const diagnosis::DiagnosisResult& r) {
    QString text;
    for (const auto& f : r.findings)
        text += QStringLiteral("\n          step %1 %2%3: %4 % on %5, ΔBIC %6, %7")
                    .arg(f.step)
                    .arg(f.cause, f.significant ? QStringLiteral(" *") : QString())
                    .arg(100 * f.gain.reduction, 0, 'f', 0)
                    .arg(f.gain.quantity)
                    .arg(f.bic_drop, 0, 'f', 0)
                    .arg(diagnosis::parametersText(f));
    return text;
}

}  // namespace driftlab::test
