// driftlab-cli diagnose: docs/diagnosis.md's JSON, plots of the residual,
// the adopted extension kept in the database.
#include <gtest/gtest.h>

#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include "db/DiagnosisStore.h"
#include "db/ModelFitStore.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

TEST(DiagnoseCli, findsAHiddenSensorLagAndKeepsTheExtension) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("campaign"));
    CliResult sim = runCli({QStringLiteral("simulate"), QStringLiteral("--out"), bundle,
                            QStringLiteral("--runs"), QStringLiteral("S1,S3,S5"),
                            QStringLiteral("--effect"), QStringLiteral("sensor_lag:T_nut=400"),
                            QStringLiteral("--seed"), QStringLiteral("5")});
    ASSERT_EQ(sim.exitCode, 0) << sim.err.constData();
    const QString dbPath = dir.filePath(QStringLiteral("lab.sqlite"));
    CliResult imported = runCli({QStringLiteral("import"), bundle, QStringLiteral("--db"), dbPath});
    ASSERT_EQ(imported.exitCode, 0) << imported.err.constData();
    const QString id = QString::fromUtf8(imported.out.trimmed());

    const QString plots = dir.filePath(QStringLiteral("plots"));
    CliResult r = runCli({QStringLiteral("diagnose"), QStringLiteral("--db"), dbPath,
                          QStringLiteral("--campaign"), id, QStringLiteral("--plots"), plots,
                          QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject d = QJsonDocument::fromJson(r.out).object();
    EXPECT_EQ(d[QStringLiteral("base_model")].toString(), QStringLiteral("screw-fdm"));
    EXPECT_EQ(d[QStringLiteral("train_runs")].toArray(), QJsonArray({"S1", "S3"}));
    EXPECT_EQ(d[QStringLiteral("test_runs")].toArray(), QJsonArray({"S5"}));
    EXPECT_GT(d[QStringLiteral("base")][QStringLiteral("test_rms_um")].toDouble(), 0);
    EXPECT_EQ(d[QStringLiteral("verdict")].toString(), QStringLiteral("sensor_lag:T_nut"));
    const QJsonArray findings = d[QStringLiteral("findings")].toArray();
    ASSERT_FALSE(findings.isEmpty());
    const QJsonObject best = findings[0].toObject();
    EXPECT_EQ(best[QStringLiteral("cause")].toString(), QStringLiteral("sensor_lag:T_nut"));
    EXPECT_NEAR(best[QStringLiteral("parameters")][QStringLiteral("tau")].toDouble(), 400, 60);
    EXPECT_GT(best[QStringLiteral("confidence")].toDouble(), 0.5);
    // The named cause's confidence keeps the share of the positioning
    // structure above the noise that it explains: at most that share.
    const double share = d[QStringLiteral("structure_explained")].toDouble(-1);
    EXPECT_GE(share, 0);
    EXPECT_LE(share, 1);
    EXPECT_LE(best[QStringLiteral("confidence")].toDouble(), share);
    EXPECT_TRUE(best[QStringLiteral("evidence")].toString().contains(QStringLiteral("T_nut")));
    // A sensor effect's gain is on that sensor's temperature; both quantities
    // are there, and the reduction is the one their figures give.
    const QJsonObject gain = best[QStringLiteral("gain")].toObject();
    EXPECT_EQ(gain[QStringLiteral("quantity")].toString(), QStringLiteral("temperature:T_nut"));
    const double before = gain[QStringLiteral("test_rms_before_K")].toDouble();
    const double after = gain[QStringLiteral("test_rms_after_K")].toDouble();
    EXPECT_LT(after, before);
    EXPECT_NEAR(gain[QStringLiteral("reduction")].toDouble(), 1 - after / before, 1e-9);
    EXPECT_GT(gain[QStringLiteral("reduction")].toDouble(), 0.5);
    EXPECT_LT(gain[QStringLiteral("positioning_rms_after_um")].toDouble(),
              gain[QStringLiteral("positioning_rms_before_um")].toDouble());
    EXPECT_EQ(d[QStringLiteral("causes")].toArray().first()[QStringLiteral("cause")].toString(),
              QStringLiteral("sensor_lag:T_nut"));
    // Step 1 sorted by held-out gain.
    for (int i = 1; i < findings.size() && findings[i][QStringLiteral("step")].toInt() == 1; ++i)
        EXPECT_LE(findings[i][QStringLiteral("gain")][QStringLiteral("reduction")].toDouble(),
                  findings[i - 1][QStringLiteral("gain")][QStringLiteral("reduction")].toDouble());
    const QJsonArray pngs = d[QStringLiteral("plots")].toArray();
    ASSERT_EQ(pngs.size(), 2);
    for (const auto& png : pngs)
        EXPECT_FALSE(QImage(png.toString()).isNull()) << qPrintable(png.toString());

    QString error;
    auto store = db::CampaignStore::open(dbPath, db::StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    const auto stored = db::diagnoses(*store, id.toLongLong());
    ASSERT_EQ(stored.size(), 1u);
    EXPECT_EQ(stored[0].verdict, QStringLiteral("sensor_lag:T_nut"));
    ASSERT_TRUE(stored[0].adopted_fit_id.has_value());
    const auto fits = db::modelFits(*store, id.toLongLong());
    ASSERT_EQ(fits.size(), 1u);
    EXPECT_EQ(fits[0].id, *stored[0].adopted_fit_id);
    EXPECT_EQ(fits[0].model, QStringLiteral("heat-transfer+sensor_lag:T_nut"));
    EXPECT_TRUE(fits[0].parameters.contains(QStringLiteral("tau")));
}

TEST(DiagnoseCli, needsHeldOutRunsAndSaysSo) {
    QTemporaryDir dir;
    CliResult sim = runCli({QStringLiteral("simulate"), QStringLiteral("--out"), dir.path(),
                            QStringLiteral("--runs"), QStringLiteral("S1")});
    ASSERT_EQ(sim.exitCode, 0) << sim.err.constData();
    CliResult one = runCli({QStringLiteral("diagnose"), dir.path()});
    EXPECT_EQ(one.exitCode, 1);
    EXPECT_TRUE(reason(one.err).contains("training and held-out runs")) << one.err.constData();
    CliResult same = runCli({QStringLiteral("diagnose"), dir.path(), QStringLiteral("--train"),
                             QStringLiteral("S1"), QStringLiteral("--test"), QStringLiteral("S1")});
    EXPECT_EQ(same.exitCode, 2) << "a usage error, refused before the campaign is read";
    EXPECT_TRUE(reason(same.err).contains("run S1 is both a training and a test run"))
        << same.err.constData();
}
