// driftlab-cli iso230-2 --spec and report --spec as a lab uses them: the
// example bundle's run accepted against a specification, each verdict
// following ISO 14253-1 from the printed numbers, PASS, FAIL and NOT PROVEN
// read back from the PDF, the campaign's own specification, and refusals.

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <cmath>

#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab::test;

namespace {

const QString kSpec =
    QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/examples/x-axis-acceptance.json");

QString writeJson(const QTemporaryDir& dir, const QString& name, const QJsonObject& object) {
    const QString path = dir.filePath(name);
    writeFile(path, QJsonDocument(object).toJson());
    return path;
}

QJsonObject acceptanceOf(const QStringList& args) {
    const CliResult r = runCli(
        QStringList{QStringLiteral("iso230-2"), exampleBundlePath(), QStringLiteral("--json")} +
        args);
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return json(r).value(QStringLiteral("acceptance")).toObject();
}

/// The example specification with these tolerances of axis X.
QJsonObject specWith(const QJsonObject& tolerances) {
    QJsonObject spec = QJsonDocument::fromJson(readFile(kSpec)).object();
    spec[QStringLiteral("axes")] = QJsonObject{
        {QStringLiteral("X"), QJsonObject{{QStringLiteral("iso230_2_um"), tolerances}}}};
    return spec;
}

}  // namespace

TEST(AcceptanceCli, everyVerdictFollowsTheDecisionRuleFromItsNumbers) {
    const QJsonObject a = acceptanceOf({QStringLiteral("--spec"), kSpec});
    ASSERT_FALSE(a.isEmpty());
    const QJsonArray decisions = a.value(QStringLiteral("decisions")).toArray();
    ASSERT_EQ(decisions.size(), 5);  // A, E, R, B, M of the example specification
    for (const QJsonValue& v : decisions) {
        const QJsonObject d = v.toObject();
        const double y = d.value(QStringLiteral("value_um")).toDouble();
        const double U = d.value(QStringLiteral("expanded_uncertainty_um")).toDouble();
        const double T = d.value(QStringLiteral("tolerance_um")).toDouble();
        const QString expected = y + U <= T  ? QStringLiteral("PASS")
                                 : y - U > T ? QStringLiteral("FAIL")
                                             : QStringLiteral("NOT PROVEN");
        EXPECT_EQ(d.value(QStringLiteral("verdict")).toString(), expected)
            << d.value(QStringLiteral("parameter")).toString().toStdString();
        EXPECT_GT(U, 0);
    }
    // The example's bed thermometer is the material temperature; the run is
    // normalised to 20 °C with the screw's expansion coefficient.
    const QJsonObject environment = a.value(QStringLiteral("environment")).toObject();
    EXPECT_EQ(environment.value(QStringLiteral("material"))
                  .toObject()
                  .value(QStringLiteral("channels"))
                  .toArray()
                  .first()
                  .toString(),
              QStringLiteral("T_bed"));
    EXPECT_EQ(environment.value(QStringLiteral("air"))
                  .toObject()
                  .value(QStringLiteral("channels"))
                  .toArray()
                  .first()
                  .toString(),
              QStringLiteral("T_air"));
    const QJsonObject normalisation = a.value(QStringLiteral("normalisation")).toObject();
    EXPECT_EQ(normalisation.value(QStringLiteral("mode")).toString(), QStringLiteral("normalised"));
    EXPECT_DOUBLE_EQ(normalisation.value(QStringLiteral("expansion_per_K")).toDouble(), 1.15e-5);
    const QJsonObject budget = a.value(QStringLiteral("uncertainty")).toObject();
    EXPECT_EQ(budget.value(QStringLiteral("contributions")).toArray().size(), 7);
    EXPECT_EQ(budget.value(QStringLiteral("eve_um")).toDouble(), 1.5);
}

TEST(AcceptanceCli, reportStatesPassFailAndNotProvenWithTheBudget) {
    // Tolerances placed around the values the run gives: A with room to
    // spare, R below what was measured beyond doubt, E on the value itself.
    const QJsonObject first = acceptanceOf({QStringLiteral("--spec"), kSpec});
    QJsonObject value, uncertainty;
    for (const QJsonValue& v : first.value(QStringLiteral("decisions")).toArray()) {
        const QJsonObject d = v.toObject();
        value[d.value(QStringLiteral("parameter")).toString()] =
            d.value(QStringLiteral("value_um"));
        uncertainty[d.value(QStringLiteral("parameter")).toString()] =
            d.value(QStringLiteral("expanded_uncertainty_um"));
    }
    const auto at = [&](const char* p, double uFactor, double extra) {
        return value.value(QLatin1String(p)).toDouble() +
               uFactor * uncertainty.value(QLatin1String(p)).toDouble() + extra;
    };
    QTemporaryDir dir;
    const QString spec = writeJson(dir, QStringLiteral("spec.json"),
                                   specWith({{QStringLiteral("A"), at("A", 1, 0.5)},
                                             {QStringLiteral("R"), at("R", -1, -0.5)},
                                             {QStringLiteral("E"), at("E", 0, 0)}}));
    const QJsonObject a = acceptanceOf({QStringLiteral("--spec"), spec});
    QStringList verdicts;
    for (const QJsonValue& v : a.value(QStringLiteral("decisions")).toArray())
        verdicts << v.toObject().value(QStringLiteral("verdict")).toString();
    EXPECT_EQ(verdicts, (QStringList{QStringLiteral("PASS"), QStringLiteral("NOT PROVEN"),
                                     QStringLiteral("FAIL")}));  // A, E, R in parameter order
    EXPECT_EQ(a.value(QStringLiteral("verdict")).toString(), QStringLiteral("FAIL"));

    const QString pdf = dir.filePath(QStringLiteral("report.pdf"));
    const CliResult r = runCli({QStringLiteral("report"), exampleBundlePath(),
                                QStringLiteral("--pdf"), pdf, QStringLiteral("--spec"), spec});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QString text = pdfText(pdf, PdfText::ReadingOrder);
    EXPECT_TRUE(text.contains(QStringLiteral("Acceptance: FAIL")));
    for (const char* phrase :
         {"PASS", "NOT PROVEN", "FAIL", "Environment and 20 °C", "Uncertainty budget",
          "environmental variation error", "Normalised to 20 °C", "T_bed"})
        EXPECT_TRUE(text.contains(QString::fromUtf8(phrase))) << phrase;
}

TEST(AcceptanceCli, driftFiguresOfEachRunAreDecidedToo) {
    const CliResult r = runCli({QStringLiteral("iso230-3"), exampleBundlePath(),
                                QStringLiteral("--spec"), kSpec, QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    bool spindle = false;
    for (const QJsonValue& run : json(r).value(QStringLiteral("runs")).toArray()) {
        const QJsonObject o = run.toObject();
        if (o.value(QStringLiteral("run")).toString() != QLatin1String("SP1")) continue;
        spindle = true;
        const QJsonArray decisions = o.value(QStringLiteral("acceptance"))
                                         .toObject()
                                         .value(QStringLiteral("decisions"))
                                         .toArray();
        ASSERT_EQ(decisions.size(), 1);  // the example specifies max_drift only
        const QJsonObject d = decisions.first().toObject();
        // The largest |drift| of the spindle's probes, against 25 µm with
        // U = 2·√((0.2/2)² + (1.5/(2√3))²) = 0.8888 µm.
        double largest = 0;
        for (const QJsonValue& p : o.value(QStringLiteral("probes")).toArray())
            largest = std::max(
                largest, std::abs(p.toObject().value(QStringLiteral("max_drift_um")).toDouble()));
        EXPECT_NEAR(d.value(QStringLiteral("value_um")).toDouble(), largest, 1e-6);
        EXPECT_NEAR(d.value(QStringLiteral("expanded_uncertainty_um")).toDouble(), 0.8888, 1e-4);
        EXPECT_EQ(d.value(QStringLiteral("verdict")).toString(),
                  largest + 0.8888 <= 25 ? QStringLiteral("PASS") : QStringLiteral("NOT PROVEN"));
    }
    EXPECT_TRUE(spindle);
}

TEST(AcceptanceCli, aCampaignCarriesItsOwnSpecification) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("campaign"));
    copyBundle(exampleBundlePath(), bundle);
    const QString campaignJson = bundle + QStringLiteral("/campaign.json");
    QJsonObject campaign = QJsonDocument::fromJson(readFile(campaignJson)).object();
    QJsonObject spec = specWith({{QStringLiteral("M"), 1000}});
    spec.remove(QStringLiteral("format"));
    campaign[QStringLiteral("acceptance")] = spec;
    writeFile(campaignJson, QJsonDocument(campaign).toJson());
    const CliResult r = runCli({QStringLiteral("iso230-2"), bundle, QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject a = json(r).value(QStringLiteral("acceptance")).toObject();
    EXPECT_EQ(a.value(QStringLiteral("verdict")).toString(), QStringLiteral("PASS"));
    // The evaluation itself is of the readings at 20 °C.
    const CliResult raw =
        runCli({QStringLiteral("iso230-2"), exampleBundlePath(), QStringLiteral("--json")});
    EXPECT_NE(json(r).value(QStringLiteral("E")).toDouble(),
              json(raw).value(QStringLiteral("E")).toDouble());
}

TEST(AcceptanceCli, refusesAMisspeltToleranceAndASpecWithoutACampaign) {
    QTemporaryDir dir;
    const QString spec =
        writeJson(dir, QStringLiteral("typo.json"), specWith({{QStringLiteral("Aa"), 10}}));
    const CliResult typo =
        runCli({QStringLiteral("iso230-2"), exampleBundlePath(), QStringLiteral("--spec"), spec});
    EXPECT_NE(typo.exitCode, 0);
    EXPECT_TRUE(reason(typo.err).contains("axes.X.iso230_2_um.'Aa': unknown key"))
        << typo.err.constData();
    const QString csv = QStringLiteral(DRIFTLAB_SOURCE_DIR "/tests/iso/data/golden_3x5.csv");
    const CliResult noCampaign =
        runCli({QStringLiteral("iso230-2"), csv, QStringLiteral("--spec"), kSpec});
    EXPECT_EQ(noCampaign.exitCode, 2);
    EXPECT_TRUE(reason(noCampaign.err).contains("--spec needs a campaign"))
        << noCampaign.err.constData();
}
