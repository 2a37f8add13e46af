// driftlab-cli fit and compare on a simulated campaign: the JSON that scripts
// rely on (docs/cli.md), fits kept in the database, clear refusals.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "db/ModelFitStore.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

/// S1, S4 and S5 of the rig, with a spindle run: written once per test binary.
const QString& simulatedBundle() {
    static QTemporaryDir dir;
    static const QString bundle = [] {
        const QString path = dir.filePath(QStringLiteral("campaign"));
        CliResult r = runCli({QStringLiteral("simulate"), QStringLiteral("--out"), path,
                              QStringLiteral("--runs"), QStringLiteral("S1,S4,S5"),
                              QStringLiteral("--spindle")});
        EXPECT_EQ(r.exitCode, 0) << r.err.constData();
        return path;
    }();
    return bundle;
}

}  // namespace

TEST(ModelCli, fitJsonHasParametersWithSigmaAndTheHeldOutScore) {
    CliResult r = runCli({QStringLiteral("fit"), simulatedBundle(), QStringLiteral("--model"),
                          QStringLiteral("heat-transfer"), QStringLiteral("--train"),
                          QStringLiteral("S1"), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject fit = json(r);
    EXPECT_EQ(fit[QStringLiteral("model")].toString(), QStringLiteral("heat-transfer"));
    EXPECT_EQ(fit[QStringLiteral("train_runs")].toArray(), QJsonArray({"S1"}));
    EXPECT_EQ(fit[QStringLiteral("test_runs")].toArray(), QJsonArray({"S4", "S5"}));
    const QJsonObject cNut = fit[QStringLiteral("parameters")][QStringLiteral("c_nut")].toObject();
    EXPECT_NEAR(cNut[QStringLiteral("value")].toDouble(), 0.11, 0.011);
    EXPECT_GT(cNut[QStringLiteral("sigma")].toDouble(), 0);
    EXPECT_EQ(fit[QStringLiteral("score_kind")].toString(), QStringLiteral("held_out"));
    const QJsonObject test = fit[QStringLiteral("test")].toObject();
    EXPECT_EQ(fit[QStringLiteral("score")][QStringLiteral("runs")].toArray(),
              QJsonArray({"S4", "S5"}));
    EXPECT_EQ(fit[QStringLiteral("score")][QStringLiteral("rms_um")].toDouble(),
              test[QStringLiteral("rms_um")].toDouble());
    EXPECT_GT(test[QStringLiteral("reduction")].toDouble(), 0.9);
    EXPECT_LT(test[QStringLiteral("rms_um")].toDouble(),
              test[QStringLiteral("peak_um")].toDouble());
}

TEST(ModelCli, fitFromTheDatabaseIsStoredWithItsRunsAndFigures) {
    QTemporaryDir dir;
    const QString dbPath = dir.filePath(QStringLiteral("campaign.sqlite"));
    CliResult imported =
        runCli({QStringLiteral("import"), simulatedBundle(), QStringLiteral("--db"), dbPath});
    ASSERT_EQ(imported.exitCode, 0) << imported.err.constData();
    const QString id = QString::fromUtf8(imported.out.trimmed());
    CliResult r =
        runCli({QStringLiteral("fit"), QStringLiteral("--db"), dbPath, QStringLiteral("--campaign"),
                id, QStringLiteral("--model"), QStringLiteral("mlr"), QStringLiteral("--train"),
                QStringLiteral("S1,S4"), QStringLiteral("--test"), QStringLiteral("S5")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();

    QString error;
    auto store = db::CampaignStore::open(dbPath, db::StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    const auto fits = db::modelFits(*store, id.toLongLong());
    ASSERT_EQ(fits.size(), 1u);
    EXPECT_EQ(fits[0].model, QStringLiteral("mlr"));
    EXPECT_EQ(fits[0].train_runs, QStringList({"S1", "S4"}));
    EXPECT_EQ(fits[0].test_runs, QStringList({"S5"}));
    EXPECT_FALSE(fits[0].parameters.isEmpty());
    EXPECT_GT(fits[0].metrics[QStringLiteral("test")][QStringLiteral("rms_um")].toDouble(), 0);
}

TEST(ModelCli, compareGivesTheCrossStateMatrixOfEveryModel) {
    CliResult r = runCli({QStringLiteral("compare"), simulatedBundle(), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject cmp = json(r);
    EXPECT_EQ(cmp[QStringLiteral("runs")].toArray(), QJsonArray({"S1", "S4", "S5"}));
    EXPECT_EQ(cmp[QStringLiteral("diagonal")].toString(),
              QStringLiteral("training score (fitted and scored on the same run)"));
    const QJsonObject models = cmp[QStringLiteral("models")].toObject();
    EXPECT_EQ(models.keys(), QStringList({"arx", "arx-all", "exponential", "heat-transfer", "mlr",
                                          "poly-position", "sensorless"}));
    for (const QString& name : models.keys()) {
        const QJsonArray m = models[name][QStringLiteral("rms_um")].toArray();
        ASSERT_EQ(m.size(), 3) << qPrintable(name);
        for (const auto& row : m) EXPECT_EQ(row.toArray().size(), 3) << qPrintable(name);
    }
    // Fitted on S1, scored on S4: the regression misses, physics does not.
    const double mlr = models[QStringLiteral("mlr")][QStringLiteral("rms_um")][0][1].toDouble();
    const double physics =
        models[QStringLiteral("heat-transfer")][QStringLiteral("rms_um")][0][1].toDouble();
    EXPECT_GT(mlr, 3 * physics);
}

TEST(ModelCli, fitTextSaysTheScoreIsHeldOutAndOnWhichRuns) {
    CliResult r = runCli({QStringLiteral("fit"), simulatedBundle(), QStringLiteral("--model"),
                          QStringLiteral("mlr"), QStringLiteral("--test"), QStringLiteral("S4")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    // Only --test: the training run is the first that is not a test run.
    // S4 runs faster than S1 and heats the screw further: below the score,
    // where its temperatures leave S1's.
    const QList<QByteArray> lines = r.out.trimmed().split('\n');
    qsizetype score = -1;
    for (qsizetype i = 0; i < lines.size(); ++i)
        if (lines[i].startsWith("held-out score on S4 (runs the fit has not seen): RMS "))
            score = i;
    ASSERT_GE(score, 0) << r.out.constData();
    // Then how much of S4 the prediction interval covers (a regression fitted
    // on one state covers little of another), and where S4 leaves S1.
    ASSERT_EQ(lines.size(), score + 4) << r.out.constData();
    EXPECT_TRUE(lines[score + 1].startsWith("prediction interval ±")) << r.out.constData();
    EXPECT_TRUE(lines[score + 1].contains("far less than it claims")) << r.out.constData();
    EXPECT_EQ(lines[score + 2],
              "beyond the training runs' temperature rises (the prediction "
              "extrapolates there):");
    EXPECT_TRUE(lines[score + 3].startsWith("  S4: ")) << r.out.constData();
    EXPECT_TRUE(lines[score + 3].contains("T_nut (nut) +")) << r.out.constData();
    CliResult json = runCli({QStringLiteral("fit"), simulatedBundle(), QStringLiteral("--model"),
                             QStringLiteral("mlr"), QStringLiteral("--test"), QStringLiteral("S1"),
                             QStringLiteral("--json")});
    ASSERT_EQ(json.exitCode, 0) << json.err.constData();
    EXPECT_EQ(QJsonDocument::fromJson(json.out).object()[QStringLiteral("train_runs")].toArray(),
              QJsonArray({"S4"}));
}

TEST(ModelCli, driftChannelOfTheSpindleRunIsATarget) {
    CliResult r = runCli({QStringLiteral("fit"), simulatedBundle(), QStringLiteral("--model"),
                          QStringLiteral("mlr"), QStringLiteral("--target"), QStringLiteral("D_z"),
                          QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    EXPECT_EQ(json(r)[QStringLiteral("train_runs")].toArray(), QJsonArray({"SP1"}));
}

TEST(ModelCli, autoChoosesOnTheTrainingRunsAndSaysWhat) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("spindle"));
    ASSERT_EQ(runCli({QStringLiteral("simulate"), QStringLiteral("--out"), bundle,
                      QStringLiteral("--runs"), QStringLiteral("S1"),
                      QStringLiteral("--spindle-runs"), QStringLiteral("4")})
                  .exitCode,
              0);
    CliResult r =
        runCli({QStringLiteral("fit"), bundle, QStringLiteral("--model"), QStringLiteral("auto"),
                QStringLiteral("--target"), QStringLiteral("D_z"), QStringLiteral("--train"),
                QStringLiteral("SP1,SP2,SP3"), QStringLiteral("--test"), QStringLiteral("SP4"),
                QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject o = json(r);
    EXPECT_EQ(o[QStringLiteral("model")].toString(), QStringLiteral("auto"));
    const QJsonObject fit = o[QStringLiteral("fit")].toObject();
    const QString said = fit[QStringLiteral("notes")].toArray().first().toString();
    EXPECT_TRUE(said.startsWith(QStringLiteral("auto chose arx"))) << qPrintable(said);
    EXPECT_TRUE(said.contains(QStringLiteral("mlr "))) << "the families it turned down, scored";
    // The lag of each chosen sensor is a parameter, and the held-out drift of
    // tens of µm is followed to well under a micrometre.
    bool hasLag = false;
    for (const QString& key : o[QStringLiteral("parameters")].toObject().keys())
        hasLag = hasLag || key.endsWith(QStringLiteral(".tau"));
    EXPECT_TRUE(hasLag);
    EXPECT_LT(o[QStringLiteral("test")].toObject()[QStringLiteral("rms_um")].toDouble(), 0.5);

    CliResult text =
        runCli({QStringLiteral("fit"), bundle, QStringLiteral("--model"), QStringLiteral("auto"),
                QStringLiteral("--target"), QStringLiteral("D_z"), QStringLiteral("--train"),
                QStringLiteral("SP1,SP2"), QStringLiteral("--test"), QStringLiteral("SP3,SP4")});
    ASSERT_EQ(text.exitCode, 0) << text.err.constData();
    EXPECT_TRUE(text.out.contains("auto chose")) << text.out.constData();
}

TEST(ModelCli, badRequestsAreRefusedWithTheReason) {
    CliResult unknown = runCli({QStringLiteral("fit"), simulatedBundle(), QStringLiteral("--model"),
                                QStringLiteral("crystal-ball")});
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_TRUE(reason(unknown.err).contains("'crystal-ball' is not a model"));
    CliResult spindle =
        runCli({QStringLiteral("fit"), simulatedBundle(), QStringLiteral("--model"),
                QStringLiteral("heat-transfer"), QStringLiteral("--train"), QStringLiteral("SP1")});
    EXPECT_EQ(spindle.exitCode, 1);
    EXPECT_TRUE(reason(spindle.err).contains("SP1")) << spindle.err.constData();
    CliResult missing =
        runCli({QStringLiteral("fit"), simulatedBundle(), QStringLiteral("--model"),
                QStringLiteral("mlr"), QStringLiteral("--train"), QStringLiteral("S9")});
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_TRUE(reason(missing.err).contains("S9")) << missing.err.constData();
}
