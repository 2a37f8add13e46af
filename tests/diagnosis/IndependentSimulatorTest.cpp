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
#include <QProcess>
#include <QTemporaryDir>
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
    QString detail;
    std::vector<test::NamedCause> named = {};
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

Outcome diagnoseBundle(const QString& directory, const QString& expected) {
    const BundleReadResult read = readBundle(directory);
    if (!read.ok()) return {QStringLiteral("refused"), read.error->toString()};
    const auto r = diagnosis::diagnose(*read.campaign);
    if (!r.ok()) return {QStringLiteral("error"), r.error};
    test::expectExclusiveConfidences(r, directory);
    QString detail = r.verdict_evidence;
    for (const QString& cause : r.causes)
        detail += QStringLiteral("\n        %1: %2")
                      .arg(cause, diagnosis::adoptedFinding(r, cause)->evidence);
    if (!r.remaining.isEmpty()) detail += QStringLiteral("\n        ") + r.remaining;
    detail += test::findingsText(r);
    return {r.causes.size() > 1 ? r.causes.join(QLatin1Char('+')) : r.verdict, detail,
            test::namedCauses(r, expected)};
}

}  // namespace

TEST(IndependentSimulator, diagnosisOnCampaignsItDidNotWrite) {
    // DRIFTLAB_INDEPENDENT_SUITE=DIR diagnoses another suite of the simulator
    // (e.g. `campaigns.py --scale 0.5`: weaker effects, for the reliability table).
    const QDir suite(qEnvironmentVariable("DRIFTLAB_INDEPENDENT_SUITE",
                                          QStringLiteral(DRIFTLAB_INDEPENDENT_SUITE)));
    const auto cases = manifest(suite);
    ASSERT_GE(cases.size(), 20u) << "the suite is written by the test independent_suite_generate";
    std::vector<Outcome> outcomes(cases.size());
    for (std::size_t i = 0; i < cases.size(); i += 2) {  // two at a time: two cores
        auto second = i + 1 < cases.size()
                          ? std::async(std::launch::async, diagnoseBundle,
                                       suite.filePath(cases[i + 1].bundle), cases[i + 1].expected)
                          : std::future<Outcome>();
        outcomes[i] = diagnoseBundle(suite.filePath(cases[i].bundle), cases[i].expected);
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
                  << test::verdictConfidence(o.named) << ")\n        " << qPrintable(o.detail)
                  << "\n";
        EXPECT_NE(o.verdict, QStringLiteral("refused")) << qPrintable(cases[i].bundle);
        EXPECT_NE(o.verdict, QStringLiteral("error")) << qPrintable(cases[i].bundle);
        // Null data, and an effect outside the library, never get a named cause.
        if (expected == QLatin1String("none") || expected == QLatin1String("unexplained")) {
            EXPECT_TRUE(o.verdict == QLatin1String("none") ||
                        o.verdict == QLatin1String("unexplained"))
                << qPrintable(cases[i].bundle) << ": " << qPrintable(o.verdict);
        }
    }
    test::printConfusion("confusion matrix, independent simulator", confusion, 36);
    std::cout << "correct: " << correct << " of " << cases.size() << "\n";
    std::vector<test::NamedCause> named;
    for (const Outcome& o : outcomes) named.insert(named.end(), o.named.begin(), o.named.end());
    EXPECT_LT(test::printReliability("reliability of the confidence, independent simulator", named),
              test::kMaxBrier)
        << "the confidences do not say how often the causes named are right";
    EXPECT_GE(double(correct), kIndependentFloor * double(cases.size()));
}

TEST(IndependentSimulator, otherDrawsCausesNearTheNoiseAndOneMaskedByTheFirstAreNamed) {
    // Other machines and noise of the simulator (seed offsets 61, 71, 81, 91),
    // where the rig's naming rules once fell short:
    // - motor heat leaving the noise but 0.08 µm (0.63 → 0.34 µm against 0.33
    //   µm) was `unexplained`: 1 − after/before read 46 %, though 85 % of the
    //   structure's RMS was gone;
    // - frame growth leaving 1.8× the noise ended the search, as "only
    //   noise", before the forced convection beneath it (and nut heat leaving
    //   1.6× before refraction);
    // - refraction lowered the held-out error by nothing (−9 %) beside the
    //   nut's larger heat in step 1, though the training runs showed it
    //   (ΔBIC 955), and was not tried again on top of the nut heat;
    // - refraction of 0.86 µm left the base model at 1.50× the reading noise
    //   and was `none`, though it took the held-out residual to the noise
    //   with confidence 0.9997;
    // - nut heat with n = 0.75, trained at 3 and 4.5 m/min and held out at 8
    //   and 12 m/min, took the held-out residual from 1.90 to 0.48 µm with
    //   confidence 1 and was `unexplained`: two close training speeds could
    //   not show the speed law (ΔBIC 5);
    // - (seed offset 91) after the nut sensor's lag, a 16 s lag of a bearing
    //   sensor was named second with confidence 1 for a fifth of that sensor's
    //   residual: the simulator puts the bearing heat over a seat 25–45 mm
    //   long around the sensor, the model into the end cell;
    // - (91) forced convection with m = 3 ranked above the hidden motor heat
    //   (46 % against 45 % of the positioning residual), though it made the
    //   screw temperatures worse (0.52 → 0.75 K) where motor heat took them to
    //   0.16 K: `unexplained`, the motor heat and the nut sensor's offset
    //   unnamed;
    // - (61) the same pair: the nut sensor's offset, masked in step 1 by the
    //   motor heat's larger error (−1 %), was not tried again on top of it
    //   (ΔBIC 18 on the training runs), and frame growth came second;
    // - (81) the same pair: the room sensor's offset (−0.14 K) took 70 % of
    //   the positioning residual and was named alone, though it pulled both
    //   bearing sensors 0.15 K from the room they read at the soaked start.
    //   Both causes are named now; the nut sensor's offset first, since it
    //   masks the motor heat in step 1 (the manifest orders by the error each
    //   adds to the positioning, where an offset adds none).
    const QDir draws(QStringLiteral(DRIFTLAB_INDEPENDENT_DRAWS));
    int bundles = 0;
    for (const QString& draw : {QStringLiteral("o61"), QStringLiteral("o71"), QStringLiteral("o81"),
                                QStringLiteral("o91")}) {
        const QDir suite(draws.filePath(draw));
        for (const Case& c : manifest(suite)) {
            const Outcome o = diagnoseBundle(suite.filePath(c.bundle), c.expected);
            std::cout << qPrintable(draw) << " " << qPrintable(c.bundle) << ": "
                      << qPrintable(o.verdict) << "\n";
            // The two causes of o81, in the order found (see above).
            QStringList found = o.verdict.split(QLatin1Char('+'));
            QStringList expected = c.expected.split(QLatin1Char('+'));
            if (draw == QLatin1String("o81")) {
                found.sort();
                expected.sort();
            }
            EXPECT_EQ(found, expected) << qPrintable(draw + QLatin1Char(' ') + c.bundle)
                                       << "\n        " << qPrintable(o.detail);
            ++bundles;
        }
    }
    EXPECT_EQ(bundles, 10) << "the draws are written by independent_draw61/71/81/91_generate";
}

TEST(IndependentSimulator, aLoggerReadingEveryFiveMinutesGetsTheSameVerdicts) {
    // The same campaigns with samples.csv thinned by Python to one row per run
    // every 300 s, as a slow data logger writes them: the interpolation must
    // not take the logger's rhythm for holes (it did: "no sample between 0 s
    // and 300 s, a gap longer than the 120 s limit" refused every one).
    const QDir suite(QStringLiteral(DRIFTLAB_INDEPENDENT_SUITE));
    QTemporaryDir work;
    const char* thin = R"(
import csv, shutil, sys
src, dst = sys.argv[1], sys.argv[2]
shutil.copytree(src, dst)
rows = list(csv.reader(open(src + '/samples.csv', newline='')))
out, last = [rows[0]], {}
for r in rows[1:]:
    if r[0] not in last or float(r[1]) - last[r[0]] >= 300:
        out.append(r)
        last[r[0]] = float(r[1])
csv.writer(open(dst + '/samples.csv', 'w', newline=''), lineterminator='\n').writerows(out)
)";
    for (const auto& [bundle, expected] :
         {std::pair{"forced_convection_m07", "forced_convection"}, {"null_a", "none"}}) {
        const QString thinned = work.filePath(QString::fromLatin1(bundle));
        QProcess python;
        python.start(QStringLiteral("python3"),
                     {QStringLiteral("-c"), QString::fromLatin1(thin),
                      suite.filePath(QString::fromLatin1(bundle)), thinned});
        ASSERT_TRUE(python.waitForFinished(60'000));
        ASSERT_EQ(python.exitCode(), 0) << python.readAllStandardError().constData();
        const Outcome o = diagnoseBundle(thinned, QString::fromLatin1(expected));
        std::cout << bundle << " every 300 s: " << qPrintable(o.verdict) << "\n";
        EXPECT_EQ(o.verdict, QString::fromLatin1(expected)) << qPrintable(o.detail);
    }
}

TEST(IndependentSimulator, aLoggerWithoutMotionCsvHasItsStrokesFilledInFromTheFeed) {
    // Loggers rarely write motion.csv: the same campaigns without it, the
    // nut's motion rebuilt from position samples 5–10 s apart. Lines through
    // them miss most strokes and named nut_heat_exponent for structure growth
    // (frame_growth_g2); the strokes filled in from the logged feed give the
    // right cause. Over the whole suite without motion.csv: 11 of 26 right
    // (6 before), 1 wrong (3), the rest left unexplained (docs/models.md).
    const QDir suite(QStringLiteral(DRIFTLAB_INDEPENDENT_SUITE));
    QTemporaryDir work;
    for (const auto& [bundle, expected] : {std::pair{"frame_growth_g2", "frame_growth"},
                                           {"forced_convection_m05", "forced_convection"}}) {
        const QString copy = work.filePath(QString::fromLatin1(bundle));
        QDir().mkpath(copy);
        for (const char* file : {"campaign.json", "samples.csv", "positioning.csv"})
            ASSERT_TRUE(QFile::copy(suite.filePath(QString::fromLatin1(bundle)) + QLatin1Char('/') +
                                        QString::fromLatin1(file),
                                    copy + QLatin1Char('/') + QString::fromLatin1(file)));
        const Outcome o = diagnoseBundle(copy, QString::fromLatin1(expected));
        std::cout << bundle << " without motion.csv: " << qPrintable(o.verdict) << "\n";
        EXPECT_EQ(o.verdict, QString::fromLatin1(expected)) << qPrintable(o.detail);
    }
}
