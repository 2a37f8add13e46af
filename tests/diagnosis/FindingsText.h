#pragma once
// What the hidden-effect suites print: every candidate's figures in a
// diagnosis, one indented line each (so that a wrong verdict shows why), the
// confusion matrix and the reliability of the confidence, and what every
// diagnosis of the suites must hold.
#include <gtest/gtest.h>

#include <QString>
#include <algorithm>
#include <cmath>
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

/// One cause a diagnosis named, what was hidden ("a", "a+b", "none",
/// "unexplained") and the confidence reported with the cause. A finding is
/// right when it is one of the hidden causes.
struct NamedCause {
    QString cause;
    QString hidden;
    double confidence = 0;
    bool right() const { return hidden.split(QLatin1Char('+')).contains(cause); }
};

inline std::vector<NamedCause> namedCauses(const diagnosis::DiagnosisResult& r,
                                           const QString& hidden) {
    std::vector<NamedCause> named;
    for (const QString& cause : r.causes)
        named.push_back({cause, hidden, diagnosis::adoptedFinding(r, cause)->confidence});
    return named;
}

/// The confidence of the verdict (the first cause named), 0 without one.
inline double verdictConfidence(const std::vector<NamedCause>& named) {
    return named.empty() ? 0.0 : named.front().confidence;
}

/// Each confidence of one step is the probability of an event that excludes
/// the others' (this finding's gain is the largest): together at most 1.
inline void expectExclusiveConfidences(const diagnosis::DiagnosisResult& r, const QString& name) {
    for (int step : {1, 2}) {
        double sum = 0;
        for (const auto& f : r.findings)
            if (f.step == step) sum += f.confidence;
        EXPECT_LE(sum, 1 + 1e-9) << qPrintable(name) << ", step " << step;
    }
}

/// A confidence that means something: over the causes named, its Brier score
/// stays below this (a constant 0.7 on causes that are all right scores 0.09).
constexpr double kMaxBrier = 0.05;

/// Of the causes named with a confidence in each band, how many, how many
/// right and their mean confidence (calibrated: the two agree); over all, the
/// Brier score (mean squared difference of confidence and rightness); then
/// the wrong ones. Returns the Brier score.
inline double printReliability(const char* title, const std::vector<NamedCause>& named) {
    std::cout << "\n" << title << ": confidence band, causes named, right, mean confidence\n";
    for (const auto& [lo, hi] :
         std::vector<std::pair<double, double>>{{0, 0.5}, {0.5, 0.7}, {0.7, 0.9}, {0.9, 1.01}}) {
        int n = 0, right = 0;
        double sum = 0;
        for (const NamedCause& c : named)
            if (c.confidence >= lo && c.confidence < hi) {
                ++n;
                right += c.right();
                sum += c.confidence;
            }
        std::cout << "  [" << lo << ", " << std::min(hi, 1.0) << ")  " << n << "  " << right << "  "
                  << (n ? sum / n : 0.0) << "\n";
    }
    double brier = 0;
    for (const NamedCause& c : named) brier += std::pow(c.confidence - c.right(), 2);
    if (!named.empty()) brier /= double(named.size());
    std::cout << "  Brier score " << brier << " over " << named.size() << " causes named\n";
    for (const NamedCause& c : named)
        if (!c.right())
            std::cout << "  wrong: " << qPrintable(c.cause) << " (confidence " << c.confidence
                      << "), hidden " << qPrintable(c.hidden) << "\n";
    return brier;
}

}  // namespace driftlab::test
