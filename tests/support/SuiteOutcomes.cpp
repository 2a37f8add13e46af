#include "tests/support/SuiteOutcomes.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <cmath>

namespace driftlab::test {
namespace {

QString fileOf(const QString& directory, const QString& name) {
    QString safe = name;
    safe.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_.-]")), QStringLiteral("_"));
    return QDir(directory).filePath(safe + QStringLiteral(".json"));
}

bool isNoCause(const QString& verdict) {
    return verdict == QLatin1String("none") || verdict == QLatin1String("unexplained");
}

}  // namespace

QString causeKinds(const QString& causes) {
    QStringList kinds;
    for (const QString& c : causes.split(QLatin1Char('+')))
        kinds << c.section(QLatin1Char(':'), 0, 0);
    return kinds.join(QLatin1Char('+'));
}

CaseOutcome outcomeOf(const QString& name, const QString& expected,
                      const diagnosis::DiagnosisResult& r) {
    CaseOutcome o;
    o.name = name;
    o.expected = expected;
    if (!r.ok()) {
        o.verdict = QStringLiteral("error");
        o.detail = r.error;
        return o;
    }
    o.verdict = r.causes.size() > 1 ? r.causes.join(QLatin1Char('+')) : r.verdict;
    o.named = namedCauses(r, expected);
    o.detail = r.verdict_evidence;
    for (const QString& cause : r.causes)
        o.detail += QStringLiteral("\n        %1: %2")
                        .arg(cause, diagnosis::adoptedFinding(r, cause)->evidence);
    if (!r.remaining.isEmpty()) o.detail += QStringLiteral("\n        ") + r.remaining;
    o.detail += findingsText(r);
    return o;
}

void expectSoundOutcome(const CaseOutcome& o, const diagnosis::DiagnosisResult& r) {
    ASSERT_TRUE(r.ok()) << qPrintable(o.name) << ": " << qPrintable(r.error);
    expectExclusiveConfidences(r, o.name);
    // Clean data never gets a named cause; an effect outside the library
    // never gets a wrong one.
    if (isNoCause(o.expected)) {
        EXPECT_TRUE(isNoCause(o.verdict))
            << qPrintable(o.name) << ": " << qPrintable(o.verdict) << "\n"
            << qPrintable(o.detail);
    }
    // Structure left unexplained is shown in both quantities against their
    // noise: it may sit on a sensor while positioning is at noise.
    if (o.verdict == QLatin1String("unexplained")) {
        EXPECT_TRUE(o.detail.contains(QStringLiteral("µm reading noise; worst temperature")) &&
                    o.detail.contains(QStringLiteral("K sensor noise")))
            << qPrintable(o.detail);
    }
}

void writeOutcome(const QString& directory, const CaseOutcome& o) {
    QJsonArray named;
    for (const NamedCause& c : o.named)
        named.append(QJsonObject{{QStringLiteral("cause"), c.cause},
                                 {QStringLiteral("hidden"), c.hidden},
                                 {QStringLiteral("confidence"), c.confidence}});
    QDir().mkpath(directory);
    QFile file(fileOf(directory, o.name));
    ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        << qPrintable(file.fileName());
    file.write(QJsonDocument(QJsonObject{{QStringLiteral("name"), o.name},
                                         {QStringLiteral("expected"), o.expected},
                                         {QStringLiteral("verdict"), o.verdict},
                                         {QStringLiteral("named"), named},
                                         {QStringLiteral("detail"), o.detail}})
                   .toJson());
}

std::vector<CaseOutcome> readOutcomes(const QString& directory, const QStringList& names) {
    std::vector<CaseOutcome> outcomes;
    for (const QString& name : names) {
        QFile file(fileOf(directory, name));
        if (!file.open(QIODevice::ReadOnly)) {
            ADD_FAILURE() << qPrintable(name) << " has no outcome in " << qPrintable(directory)
                          << ": its case did not run";
            continue;
        }
        const QJsonObject j = QJsonDocument::fromJson(file.readAll()).object();
        CaseOutcome o{j[QStringLiteral("name")].toString(),
                      j[QStringLiteral("expected")].toString(),
                      j[QStringLiteral("verdict")].toString(),
                      {},
                      j[QStringLiteral("detail")].toString()};
        for (const QJsonValue& c : j[QStringLiteral("named")].toArray())
            o.named.push_back({c[QStringLiteral("cause")].toString(),
                               c[QStringLiteral("hidden")].toString(),
                               c[QStringLiteral("confidence")].toDouble()});
        outcomes.push_back(std::move(o));
    }
    return outcomes;
}

void expectSuiteVerdict(const QString& suite, const std::vector<CaseOutcome>& outcomes,
                        double floor, bool calibrated) {
    ConfusionMatrix confusion;
    std::vector<NamedCause> named;
    int correct = 0;
    QString wrong;
    for (const CaseOutcome& o : outcomes) {
        correct += o.right();
        const QString column =
            causeKinds(o.verdict) + (!o.right() && causeKinds(o.verdict) == causeKinds(o.expected)
                                         ? QStringLiteral(" (other channel)")
                                         : QString());
        confusion[causeKinds(o.expected)][column]++;
        named.insert(named.end(), o.named.begin(), o.named.end());
        if (!o.right())
            wrong += QStringLiteral("\n  %1: expected %2, got %3\n        %4")
                         .arg(o.name, o.expected, o.verdict, o.detail);
        if (o.expected == QLatin1String("none")) {
            EXPECT_EQ(o.verdict, QStringLiteral("none"))
                << qPrintable(suite) << ", " << qPrintable(o.name);
        }
    }
    QString matrix;
    for (const auto& [expected, verdicts] : confusion) {
        matrix += QStringLiteral("\n  ") + expected.leftJustified(36);
        for (const auto& [verdict, n] : verdicts)
            matrix += QStringLiteral("  %1 ×%2").arg(verdict).arg(n);
    }
    EXPECT_GE(double(correct), floor * double(outcomes.size()))
        << qPrintable(suite) << ": " << correct << " of " << outcomes.size()
        << " named right; confusion matrix (rows: hidden, columns: verdict):" << qPrintable(matrix)
        << "\nwrong:" << qPrintable(wrong);
    if (!calibrated) return;
    double brier = 0;
    for (const NamedCause& c : named) brier += std::pow(c.confidence - c.right(), 2);
    if (!named.empty()) brier /= double(named.size());
    EXPECT_LT(brier, kMaxBrier) << qPrintable(suite)
                                << ": the confidences do not say how often the causes named are "
                                   "right (Brier score over "
                                << named.size() << " causes)";
}

}  // namespace driftlab::test
