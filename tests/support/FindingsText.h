#pragma once
// What the hidden-effect suites show of a diagnosis when a case fails: every
// candidate's figures, one indented line each (so that a wrong verdict shows
// why); the causes it named; and what every diagnosis of the suites must hold.
#include <gtest/gtest.h>

#include <QString>
#include <algorithm>
#include <cmath>
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

}  // namespace driftlab::test
