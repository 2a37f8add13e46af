// driftlab-cli with a server store (docs/lab-store.md): import, info, export
// and fit through --db postgresql://…; rigs that log into one server at once;
// a server restart in the middle of a run. Real processes, the real server
// of the test cluster (PgTestServer.h).
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QThread>

#include "core/bundle/BundleReader.h"
#include "db/CampaignStore.h"
#include "db/ModelFitStore.h"
#include "tests/postgres/PgTestServer.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

Campaign load(const QString& store, qint64 id) {
    QString error;
    auto opened = db::CampaignStore::open(store, db::StoreAccess::ReadOnly, &error);
    EXPECT_TRUE(opened) << qPrintable(error);
    auto c = opened ? opened->loadCampaign(id, &error) : std::nullopt;
    EXPECT_TRUE(c) << qPrintable(error);
    return c ? *c : Campaign{};
}

/// Two moving states at 1 s sampling: 1,500 s of run time (S1 900 s, S2 600 s).
QString writeShortProcedure(const QTemporaryDir& dir) {
    const QString path = dir.filePath(QStringLiteral("short.json"));
    writeFile(path, R"({"format": "driftlab.procedure/1", "name": "server test",
        "kind": "moving-states", "travel_mm": [0, 700], "sample_interval_s": 1,
        "moving_states": {"targets": 5, "block_s": 300, "cooldown_interval_s": 300,
          "states": [{"run_id": "S1", "feed_mm_min": 8000, "range_mm": [210, 490],
                      "warmup_s": 600, "cooldown_s": 300},
                     {"run_id": "S2", "feed_mm_min": 4000, "range_mm": [210, 490],
                      "warmup_s": 300, "cooldown_s": 300}]}})");
    return path;
}

QProcess* startRun(QObject* parent, const QString& procedure, const QString& url,
                   const QString& spool, double speedup) {
    auto* p = new QProcess(parent);
    p->start(QStringLiteral(DRIFTLAB_CLI),
             {"run", "--procedure", procedure, "--rig", "sim", "--db", url, "--spool", spool,
              "--speedup", QString::number(speedup), "--json"});
    return p;
}

}  // namespace

TEST(ServerCli, importInfoExportAndFitWorkOnAServerStore) {
    DRIFTLAB_REQUIRE_PG_CLUSTER();
    const QString url = PgTestServer::freshDatabase(QStringLiteral("cli_store"));
    const QString bundle = simulatedCampaign(QStringLiteral("S1,S4,S5"), 3);
    const CliResult imported = runCli({"import", bundle, "--db", url});
    ASSERT_EQ(imported.exitCode, 0) << imported.err.constData();
    const QString id = QString::fromUtf8(imported.out.trimmed());

    // The same bundle again is noticed on the server as in a file.
    const CliResult again = runCli({"import", bundle, "--db", url});
    EXPECT_EQ(again.exitCode, 1);
    EXPECT_TRUE(reason(again.err).contains("is already in")) << again.err.constData();

    const CliResult fromServer = runCli({"info", "--db", url, "--campaign", id, "--json"});
    const CliResult fromBundle = runCli({"info", bundle, "--json"});
    ASSERT_EQ(fromServer.exitCode, 0) << fromServer.err.constData();
    EXPECT_EQ(json(fromServer), json(fromBundle));

    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("exported"));
    const CliResult exported = runCli({"export", "--db", url, "--campaign", id, "--out", out});
    ASSERT_EQ(exported.exitCode, 0) << exported.err.constData();
    const bundle::BundleReadResult original = bundle::readBundle(bundle),
                                   back = bundle::readBundle(out);
    ASSERT_TRUE(back.ok()) << qPrintable(back.error->toString());
    EXPECT_EQ(*back.campaign, *original.campaign);

    const CliResult fit = runCli({"fit", "--db", url, "--campaign", id, "--model", "mlr", "--train",
                                  "S1,S4", "--test", "S5"});
    ASSERT_EQ(fit.exitCode, 0) << fit.err.constData();
    QString error;
    auto store = db::CampaignStore::open(url, db::StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    const auto fits = db::modelFits(*store, id.toLongLong());
    ASSERT_EQ(fits.size(), 1u);
    EXPECT_EQ(fits[0].model, QStringLiteral("mlr"));
}

TEST(ServerCli, aForeignDatabaseIsRefusedWithTheReason) {
    DRIFTLAB_REQUIRE_PG_CLUSTER();
    const QString url = PgTestServer::freshDatabase(QStringLiteral("cli_foreign"));
    PgTestServer::rawSql(QStringLiteral("cli_foreign"),
                         {QStringLiteral("CREATE TABLE orders (id int)")});
    const CliResult r =
        runCli({"import", simulatedCampaign(QStringLiteral("S1,S4,S5"), 3), "--db", url});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(reason(r.err).contains("not a DriftLab store")) << r.err.constData();
}

TEST(ServerCli, twoRigsLogIntoOneServerAtOnce) {
    DRIFTLAB_REQUIRE_PG_CLUSTER();
    const QString url = PgTestServer::freshDatabase(QStringLiteral("two_rigs"));
    QTemporaryDir dir;
    const QString procedure = writeShortProcedure(dir);
    QObject owner;
    const QString spools[2] = {dir.filePath(QStringLiteral("rig1.sqlite")),
                               dir.filePath(QStringLiteral("rig2.sqlite"))};
    QProcess* rigs[2] = {startRun(&owner, procedure, url, spools[0], 150),
                         startRun(&owner, procedure, url, spools[1], 150)};
    QJsonObject results[2];
    for (int k = 0; k < 2; ++k) {
        ASSERT_TRUE(rigs[k]->waitForFinished(120'000));
        ASSERT_EQ(rigs[k]->exitCode(), 0) << rigs[k]->readAllStandardError().constData();
        results[k] = QJsonDocument::fromJson(rigs[k]->readAllStandardOutput()).object();
        EXPECT_EQ(results[k][QStringLiteral("state")].toString(), QStringLiteral("finished"));
    }
    const qint64 ids[2] = {results[0][QStringLiteral("campaign")].toInteger(),
                           results[1][QStringLiteral("campaign")].toInteger()};
    EXPECT_NE(ids[0], ids[1]);
    for (int k = 0; k < 2; ++k) {
        const Campaign onServer = load(url, ids[k]);
        const Campaign inSpool =
            load(spools[k], results[k][QStringLiteral("spool_campaign")].toInteger());
        ASSERT_EQ(inSpool.runs.size(), 2u);
        EXPECT_GE(inSpool.runs[0].samples.rowCount(), 900u);
        EXPECT_EQ(onServer, inSpool) << "rig " << k + 1;
    }
}

TEST(ServerCli, aServerRestartMidRunLosesAndDuplicatesNothing) {
    DRIFTLAB_REQUIRE_PG_CLUSTER();
    const QString url = PgTestServer::freshDatabase(QStringLiteral("restart"));
    QTemporaryDir dir;
    const QString procedure = writeShortProcedure(dir);
    const QString spool = dir.filePath(QStringLiteral("rig.sqlite"));
    QObject owner;
    // 1,500 s of run time at 75x: about 20 s of logging.
    QProcess* rig = startRun(&owner, procedure, url, spool, 75);
    ASSERT_TRUE(rig->waitForStarted());
    QThread::msleep(5000);
    ASSERT_TRUE(PgTestServer::stopServer());
    QThread::msleep(4000);  // the rig logs on into its spool meanwhile
    ASSERT_TRUE(PgTestServer::startServer());
    ASSERT_TRUE(rig->waitForFinished(120'000));
    const QByteArray err = rig->readAllStandardError();
    ASSERT_EQ(rig->exitCode(), 0) << err.constData();
    const QJsonObject result = QJsonDocument::fromJson(rig->readAllStandardOutput()).object();
    EXPECT_EQ(result[QStringLiteral("state")].toString(), QStringLiteral("finished"));

    // One message for the outage and one for the recovery, not one per retry.
    EXPECT_EQ(err.count("upload: "), 2) << err.constData();
    EXPECT_TRUE(err.contains("is back after")) << err.constData();

    const Campaign inSpool = load(spool, result[QStringLiteral("spool_campaign")].toInteger());
    const Campaign onServer = load(url, result[QStringLiteral("campaign")].toInteger());
    ASSERT_EQ(inSpool.runs.size(), 2u);
    EXPECT_GE(inSpool.runs[0].samples.rowCount() + inSpool.runs[1].samples.rowCount(), 1500u);
    // Every sample, reading, motion segment on the server exactly once.
    EXPECT_EQ(onServer, inSpool);

    // The runs' events too, once each, with their campaign.
    auto eventCount = [](const QString& store, const QString& where) {
        QString error;
        auto opened = db::CampaignStore::open(store, db::StoreAccess::ReadOnly, &error);
        EXPECT_TRUE(opened) << qPrintable(error);
        QSqlQuery q(opened->database());
        EXPECT_TRUE(q.exec(QStringLiteral("SELECT count(*) FROM event_log WHERE run_id IS NOT "
                                          "NULL") +
                           where));
        return q.next() ? q.value(0).toLongLong() : -1;
    };
    const qint64 spoolEvents = eventCount(spool, {});
    EXPECT_GE(spoolEvents, 2);
    EXPECT_EQ(eventCount(url, {}), spoolEvents);
    EXPECT_EQ(eventCount(url, QStringLiteral(" AND campaign_id IS NULL")), 0);

    // A later sync finds nothing left to upload.
    const CliResult sync = runCli({"sync", "--spool", spool, "--db", url, "--json"});
    ASSERT_EQ(sync.exitCode, 0) << sync.err.constData();
    EXPECT_EQ(json(sync)[QStringLiteral("new_runs")].toInt(), 0);
    EXPECT_EQ(json(sync)[QStringLiteral("blocks_written")].toInt(), 0);
    EXPECT_EQ(json(sync)[QStringLiteral("rows_added")].toInt(), 0);
}

TEST(ServerCli, aRunWhileTheServerIsAwayIsUploadedByALaterSync) {
    DRIFTLAB_REQUIRE_PG_CLUSTER();
    QTemporaryDir dir;
    const QString procedure = writeShortProcedure(dir);
    const QString spool = dir.filePath(QStringLiteral("rig.sqlite"));
    // Nothing listens on port 1: the server is away for the whole run.
    const QString away = QStringLiteral("postgresql://driftlab@127.0.0.1:1/lab");
    const CliResult run = runCli({"run", "--procedure", procedure, "--rig", "sim", "--db", away,
                                  "--spool", spool, "--upload-timeout", "1"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(reason(run.err).contains("driftlab-cli sync --spool " + spool.toUtf8()))
        << run.err.constData();

    const QString url = PgTestServer::freshDatabase(QStringLiteral("later"));
    const CliResult sync = runCli({"sync", "--spool", spool, "--db", url, "--json"});
    ASSERT_EQ(sync.exitCode, 0) << sync.err.constData();
    EXPECT_EQ(json(sync)[QStringLiteral("new_campaigns")].toInt(), 1);
    EXPECT_EQ(json(sync)[QStringLiteral("new_runs")].toInt(), 2);
    QString error;
    auto server = db::CampaignStore::open(url, db::StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(server) << qPrintable(error);
    const auto list = server->listCampaigns();
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(load(url, list[0].id), load(spool, 1));
}
