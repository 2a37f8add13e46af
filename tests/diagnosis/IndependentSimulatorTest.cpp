// The diagnosis on campaigns it did not write: tests/independent_sim, a second
// implementation of DESIGN.md section 4 in Python (another discretisation,
// realistic motion with overrun and dwells, its own sampling, noise, geometry
// and channel names, effects whose form is not the candidates'). Thresholds
// are the ones set on the rig's suite (HiddenEffectTest), unchanged.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <future>
#include <iostream>
#include <map>

#include "core/bundle/BundleReader.h"
#include "core/diagnosis/Diagnosis.h"
#include "tests/diagnosis/FindingsText.h"

using namespace driftlab;

namespace {

/// Share of the independent suite named right, as issue 10 asks (the rig's
/// thresholds unchanged; see docs/diagnosis.md for the confusion matrix).
constexpr double kIndependentFloor = 0.9;

struct Case {
    QString bundle;
    QString expected;  ///< "none", "unexplained", a cause, or "a+b" for two in order
};

struct Outcome {
    QString verdict;  ///< as `expected` is written
    double confidence = 0;
    QString detail;
};

std::vector<Case> manifest(const QDir& suite) {
    QFile file(suite.filePath(QStringLiteral("manifest.json")));
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << qPrintable(file.fileName());
    std::vector<Case> cases;
    for (const QJsonValue& v : QJsonDocument::fromJson(file.readAll()).array()) {
        QStringList expected;
        for (const QJsonValue& e : v[QStringLiteral("expected")].toArray())
            expected << e.toString();
        cases.push_back(
            {v[QStringLiteral("bundle")].toString(),
             expected.isEmpty() ? QStringLiteral("none") : expected.join(QLatin1Char('+'))});
    }
    return cases;
}

Outcome diagnoseBundle(const QString& directory) {
    const BundleReadResult read = readBundle(directory);
    if (!read.ok()) return {QStringLiteral("refused"), 0, read.error->toString()};
    const auto r = diagnosis::diagnose(*read.campaign);
    if (!r.ok()) return {QStringLiteral("error"), 0, r.error};
    const auto* named =
        r.causes.isEmpty() ? nullptr : diagnosis::adoptedFinding(r, r.causes.front());
    QString detail = r.verdict_evidence;
    for (const QString& cause : r.causes)
        detail += QStringLiteral("\n        %1: %2")
                      .arg(cause, diagnosis::adoptedFinding(r, cause)->evidence);
    if (!r.remaining.isEmpty()) detail += QStringLiteral("\n        ") + r.remaining;
    detail += test::findingsText(r);
    return {r.causes.size() > 1 ? r.causes.join(QLatin1Char('+')) : r.verdict,
            named ? named->confidence : 0, detail};
}

}  // namespace

TEST(IndependentSimulator, diagnosisOnCampaignsItDidNotWrite) {
    const QDir suite(QStringLiteral(DRIFTLAB_INDEPENDENT_SUITE));
    const auto cases = manifest(suite);
    ASSERT_GE(cases.size(), 20u) << "the suite is written by the test independent_suite_generate";
    std::vector<Outcome> outcomes(cases.size());
    for (std::size_t i = 0; i < cases.size(); i += 2) {  // two at a time: two cores
        auto second = i + 1 < cases.size() ? std::async(std::launch::async, diagnoseBundle,
                                                        suite.filePath(cases[i + 1].bundle))
                                           : std::future<Outcome>();
        outcomes[i] = diagnoseBundle(suite.filePath(cases[i].bundle));
        if (second.valid()) outcomes[i + 1] = second.get();
    }
    test::ConfusionMatrix confusion;
    int correct = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const Outcome& o = outcomes[i];
        const QString& expected = cases[i].expected;
        const bool ok = o.verdict == expected;
        correct += ok;
        const auto kind = [](const QString& cause) {
            QStringList parts;
            for (const QString& c : cause.split(QLatin1Char('+'))) parts << c.section(':', 0, 0);
            return parts.join(QLatin1Char('+'));
        };
        confusion[kind(expected)][kind(o.verdict)]++;
        std::cout << (ok ? "  ok    " : "  WRONG ") << qPrintable(cases[i].bundle) << ": expected "
                  << qPrintable(expected) << ", got " << qPrintable(o.verdict) << " (confidence "
                  << o.confidence << ")\n        " << qPrintable(o.detail) << "\n";
        EXPECT_NE(o.verdict, QStringLiteral("refused")) << qPrintable(cases[i].bundle);
        EXPECT_NE(o.verdict, QStringLiteral("error")) << qPrintable(cases[i].bundle);
        // Null data never gets a named cause.
        if (expected == QLatin1String("none")) {
            EXPECT_TRUE(o.verdict == QLatin1String("none") ||
                        o.verdict == QLatin1String("unexplained"))
                << qPrintable(cases[i].bundle) << ": " << qPrintable(o.verdict);
        }
    }
    test::printConfusion("confusion matrix, independent simulator", confusion, 36);
    std::cout << "correct: " << correct << " of " << cases.size() << "\n";
    std::vector<test::VerdictOutcome> reliability;
    for (std::size_t i = 0; i < cases.size(); ++i)
        reliability.push_back({outcomes[i].verdict, cases[i].expected, outcomes[i].confidence});
    test::printReliability("reliability (named causes), independent simulator", reliability);
    EXPECT_GE(double(correct), kIndependentFloor * double(cases.size()));
}
