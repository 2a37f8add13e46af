// `driftlab-cli run`: every shipped procedure on the simulated rig gives a
// campaign the models and evaluations take; the logger killed with SIGKILL
// mid-run loses at most the last second, leaves a consistent store, and
// `--resume` continues the run into the run that was never killed.
#include <gtest/gtest.h>

#include <QDir>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QThread>
#include <csignal>

#include "db/CampaignStore.h"
#include "db/RunLogger.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

const QString kProcedures = QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/procedures/");

QString runAndGetCampaign(const QString& procedure, const QString& db) {
    const CliResult r = runCli({"run", "--procedure", procedure, "--rig", "sim", "--db", db});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return QString::fromUtf8(r.out.trimmed());
}

/// Two moving states at 1 s sampling, short enough to run at speed-up 20.
QString writeShortProcedure(const QTemporaryDir& dir) {
    const QString path = dir.filePath(QStringLiteral("short.json"));
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    f.write(R"({"format": "driftlab.procedure/1", "name": "kill test", "kind": "moving-states",
        "travel_mm": [0, 700], "sample_interval_s": 1,
        "moving_states": {"targets": 5, "block_s": 300, "cooldown_interval_s": 300,
          "states": [{"run_id": "S1", "feed_mm_min": 8000, "range_mm": [210, 490],
                      "warmup_s": 600, "cooldown_s": 300},
                     {"run_id": "S2", "feed_mm_min": 4000, "range_mm": [210, 490],
                      "warmup_s": 300, "cooldown_s": 300}]}})");
    return path;
}

Campaign load(const QString& db, qint64 id) {
    QString error;
    auto store = db::CampaignStore::open(db, db::StoreAccess::ReadOnly, &error);
    EXPECT_TRUE(store) << error.toStdString();
    auto c = store ? store->loadCampaign(id, &error) : std::nullopt;
    EXPECT_TRUE(c) << error.toStdString();
    return c ? *c : Campaign{};
}

}  // namespace

TEST(RunCli, everyShippedProcedureRunsOnTheSimulatedRigAndIsEvaluated) {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("lab.sqlite"));
    auto ok = [&](const QStringList& args) {
        const CliResult r = runCli(args);
        EXPECT_EQ(r.exitCode, 0) << args.join(' ').toStdString() << "\n" << r.err.constData();
        return QString::fromUtf8(r.out);
    };
    const QString iso2 = runAndGetCampaign(kProcedures + "iso230-2-x-axis.json", db);
    EXPECT_TRUE(
        ok({"iso230-2", "--db", db, "--campaign", iso2}).contains("bidirectional accuracy"));
    const QString pilgrim = runAndGetCampaign(kProcedures + "iso230-2-pilgrim.json", db);
    EXPECT_TRUE(ok({"iso230-2", "--db", db, "--campaign", pilgrim}).contains("repeatability"));

    const QString iso3 = runAndGetCampaign(kProcedures + "iso230-3-x-axis.json", db);
    EXPECT_TRUE(ok({"iso230-3", "--db", db, "--campaign", iso3}).contains("max drift"));
    const QString fitIso3 = ok({"fit", "--db", db, "--campaign", iso3, "--model", "mlr"});
    EXPECT_TRUE(fitIso3.contains("of the thermal error removed")) << fitIso3.toStdString();

    // The five moving states: a model fitted on S1 scored on S3, held out.
    const QString moving = runAndGetCampaign(kProcedures + "moving-states-s1-s5.json", db);
    const QString fit = ok({"fit", "--db", db, "--campaign", moving, "--model", "heat-transfer",
                            "--train", "S1", "--test", "S3", "--json"});
    const double removed =
        QJsonDocument::fromJson(fit.toUtf8()).object()["test"].toObject()["reduction"].toDouble();
    EXPECT_GT(removed, 0.9) << fit.toStdString();

    const QString spindle = runAndGetCampaign(kProcedures + "spindle-iso230-3.json", db);
    EXPECT_TRUE(ok({"fit", "--db", db, "--campaign", spindle, "--model", "mlr", "--target", "D_z"})
                    .contains("of the thermal error removed"));
    const QString etve = runAndGetCampaign(kProcedures + "etve-8h.json", db);
    EXPECT_TRUE(ok({"iso230-3", "--db", db, "--campaign", etve}).contains("D_z"));
    EXPECT_TRUE(ok({"fit", "--db", db, "--campaign", etve, "--model", "mlr", "--target", "D_z"})
                    .contains("of the thermal error removed"));
}

TEST(RunCli, killedLoggerLosesAtMostTheLastSecondAndResumes) {
    QTemporaryDir dir;
    const QString procedure = writeShortProcedure(dir);
    const QString db = dir.filePath(QStringLiteral("killed.sqlite"));
    constexpr double kSpeedup = 20;  // 20 samples per wall-clock second
    QProcess logger;
    QElapsedTimer sinceStart;
    sinceStart.start();
    logger.start(QStringLiteral(DRIFTLAB_CLI),
                 {"run", "--procedure", procedure, "--rig", "sim", "--db", db, "--speedup",
                  QString::number(kSpeedup)});
    ASSERT_TRUE(logger.waitForStarted());
    QThread::msleep(3000);
    ::kill(pid_t(logger.processId()), SIGKILL);
    const double killedAfter_s = sinceStart.nsecsElapsed() * 1e-9;
    logger.waitForFinished();
    ASSERT_EQ(logger.exitStatus(), QProcess::CrashExit);

    QString error;
    auto store = db::CampaignStore::open(db, db::StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(store) << error.toStdString();
    {
        QSqlQuery q(store->database());
        ASSERT_TRUE(q.exec(QStringLiteral("PRAGMA integrity_check")) && q.next());
        EXPECT_EQ(q.value(0).toString(), QStringLiteral("ok"));
    }
    // The run was being logged when the process died: it is marked interrupted.
    const std::vector<qint64> interrupted = db::markInterruptedRuns(*store, &error);
    ASSERT_EQ(interrupted.size(), 1u) << error.toStdString();
    const auto state = db::loggedRunState(*store, interrupted.front(), &error);
    ASSERT_TRUE(state);
    EXPECT_EQ(state->status, QStringLiteral("interrupted"));
    EXPECT_EQ(state->name, QStringLiteral("S1"));
    // The run can be no further than the wall-clock time since the process
    // started; what was logged reaches to at most 1 s (plus 0.5 s for the
    // process to start) before that.
    const double reachable_s = killedAfter_s * kSpeedup;
    ASSERT_TRUE(state->last_sample_s);
    EXPECT_GE(*state->last_sample_s, reachable_s - 1.5 * kSpeedup)
        << "killed after " << killedAfter_s << " s: run time reachable " << reachable_s
        << " s, logged up to " << *state->last_sample_s << " s (" << state->rows << " rows)";
    EXPECT_EQ(state->rows, qint64(*state->last_sample_s) + 1);  // 1 s sampling from 0, no hole
    const qint64 campaignId = state->campaign_id;
    store.reset();

    const CliResult resumed = runCli({"run", "--procedure", procedure, "--rig", "sim", "--db", db,
                                      "--resume", QString::number(interrupted.front())});
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err.constData();
    EXPECT_EQ(resumed.out.trimmed().toLongLong(), campaignId);

    // The resumed campaign is the campaign of a run never killed.
    const QString clean = dir.filePath(QStringLiteral("clean.sqlite"));
    const qint64 cleanId = runAndGetCampaign(procedure, clean).toLongLong();
    const Campaign a = load(db, campaignId), b = load(clean, cleanId);
    ASSERT_EQ(a.runs.size(), 2u);
    ASSERT_EQ(b.runs.size(), 2u);
    for (std::size_t r = 0; r < 2; ++r) {
        EXPECT_EQ(a.runs[r].samples, b.runs[r].samples) << r;
        EXPECT_EQ(a.runs[r].positioning, b.runs[r].positioning) << r;
        EXPECT_EQ(a.runs[r].motion, b.runs[r].motion) << r;
    }
}

TEST(RunCli, badRequestsNameTheOptionAndWhy) {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("lab.sqlite"));
    const CliResult missing = runCli({"run", "--procedure", dir.filePath("none.json"), "--db", db});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(reason(missing.err).contains("none.json")) << missing.err.constData();
    const CliResult rig =
        runCli({"run", "--procedure", kProcedures + "etve-8h.json", "--db", db, "--rig", "serial"});
    EXPECT_EQ(rig.exitCode, 2);
    EXPECT_TRUE(reason(rig.err).contains("--rig")) << rig.err.constData();
    const CliResult map = runCli({"run", "--procedure", kProcedures + "etve-8h.json", "--db", db,
                                  "--rig", "modbus://127.0.0.1:1502"});
    EXPECT_EQ(map.exitCode, 2);
    EXPECT_TRUE(reason(map.err).contains("--device-map")) << map.err.constData();
    const CliResult resume =
        runCli({"run", "--procedure", kProcedures + "etve-8h.json", "--db", db, "--resume", "x1"});
    EXPECT_EQ(resume.exitCode, 2);
    EXPECT_TRUE(reason(resume.err).contains("--resume")) << resume.err.constData();
}
