#pragma once
// What the hidden-effect suites print: every candidate's figures in a
// diagnosis, one indented line each (so that a wrong verdict shows why), the
// confusion matrix and the reliability of the confidence.
#include <QString>
#include <algorithm>
#include <iostream>
#include <map>
#include <utility>
#include <vector>

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

/// A verdict, what was hidden, and the confidence reported with the verdict.
struct VerdictOutcome {
    QString verdict;
    QString expected;
    double confidence = 0;
};

/// Of the named causes (not `none`, not `unexplained`) reported with a
/// confidence in each band, how many and how many right.
inline void printReliability(const char* title, const std::vector<VerdictOutcome>& outcomes) {
    std::cout << "\n" << title << ": confidence band, count, right\n";
    for (const auto& [lo, hi] :
         std::vector<std::pair<double, double>>{{0, 0.5}, {0.5, 0.7}, {0.7, 0.9}, {0.9, 1.01}}) {
        int n = 0, right = 0;
        for (const VerdictOutcome& o : outcomes)
            if (o.verdict != QLatin1String("none") && o.verdict != QLatin1String("unexplained") &&
                o.confidence >= lo && o.confidence < hi) {
                ++n;
                right += o.verdict == o.expected;
            }
        std::cout << "  [" << lo << ", " << std::min(hi, 1.0) << ")  " << n << "  " << right
                  << "\n";
    }
}

}  // namespace driftlab::test
