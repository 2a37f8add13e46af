#pragma once
// What the hidden-effect suites print: every candidate's figures in a
// diagnosis, one indented line each (so that a wrong verdict shows why), and
// the confusion matrix.
#include <QString>
#include <iostream>
#include <map>

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

/// Rows: the hidden cause(s); columns: each verdict given and how often.
using ConfusionMatrix = std::map<QString, std::map<QString, int>>;

inline void printConfusion(const char* title, const ConfusionMatrix& confusion, int rowWidth) {
    std::cout << "\n" << title << " (rows: hidden, columns: verdict)\n";
    for (const auto& [expected, verdicts] : confusion) {
        std::cout << "  " << qPrintable(expected.leftJustified(rowWidth));
        for (const auto& [verdict, n] : verdicts)
            std::cout << "  " << qPrintable(verdict) << " ×" << n;
        std::cout << "\n";
    }
}

}  // namespace driftlab::test
