#pragma once
// The hidden-effect suites as one ctest case per campaign: each case
// diagnoses its campaign, checks what every diagnosis must hold, and writes
// its outcome to a file; the suite's own case then reads them all and checks
// what holds over the suite (the share named right, the confusion matrix,
// the reliability of the confidence). The outcome files also feed
// docs/validation.md.

#include <QString>
#include <QStringList>
#include <vector>

#include "core/diagnosis/Diagnosis.h"
#include "tests/support/FindingsText.h"

namespace driftlab::test {

/// What one campaign's diagnosis gave, against what was hidden in it.
struct CaseOutcome {
    QString name;
    QString expected;  ///< "none", "unexplained", a cause, or "a+b" for two in order
    QString verdict;   ///< written as `expected` is
    std::vector<NamedCause> named;
    QString detail;  ///< the evidence and every finding, for a failure message
    bool right() const { return verdict == expected; }
};

/// The outcome of `result` on a campaign with `expected` hidden; `ordered`:
/// two causes must come in the expected order.
CaseOutcome outcomeOf(const QString& name, const QString& expected,
                      const diagnosis::DiagnosisResult& result);

/// What every diagnosis must hold: confidences of one step that exclude each
/// other, no named cause on null data or for an effect outside the library,
/// and structure left unexplained described in both quantities.
void expectSoundOutcome(const CaseOutcome& outcome, const diagnosis::DiagnosisResult& result);

/// Writes the outcome to `directory`/<name>.json, replacing an older one.
void writeOutcome(const QString& directory, const CaseOutcome& outcome);

/// The outcomes of `names` from `directory`; a missing one is a test failure.
std::vector<CaseOutcome> readOutcomes(const QString& directory, const QStringList& names);

/// Over the suite: at least `floor` of the campaigns named right, null data
/// always `none`, and (`calibrated`) the confidences' Brier score below
/// kMaxBrier. A failure shows the confusion matrix and every wrong campaign
/// with its evidence.
void expectSuiteVerdict(const QString& suite, const std::vector<CaseOutcome>& outcomes,
                        double floor, bool calibrated = true);

/// "sensor_lag:T_nut+frame_growth" → "sensor_lag+frame_growth": the kind of
/// each cause, for the confusion matrix.
QString causeKinds(const QString& causes);

}  // namespace driftlab::test
