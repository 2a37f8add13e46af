// `driftlab-cli run` on real devices: Debian's pymodbus serving the
// temperature module and the controller (independent implementations of
// docs/devices.md and docs/modbus-register-map.md) on 127.0.0.1. The module
// is killed mid-run and comes back: its columns have a hole and the log a
// gap; the controller's columns never stop.
#include <gtest/gtest.h>

#include <QSqlQuery>
#include <QTemporaryDir>
#include <QThread>
#include <cmath>

#include "db/CampaignStore.h"
#include "tests/acquisition/DevicePeer.h"
#include "tests/cli/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

TEST(RunDeviceCli, pymodbusModuleKilledMidRunLeavesAGapTheControllerKeepsLogging) {
    if (const QString why = peerUnavailable(); !why.isEmpty()) GTEST_SKIP() << why.toStdString();
    int modulePort = 0, controllerPort = 0;
    auto module = startTemperaturePeer(0, &modulePort);
    auto controller = startControllerPeer(0, &controllerPort,
                                          {"--position-mm", "123.4567", "--feed-mm-min", "-2500",
                                           "--torque-nm", "1.25", "--state", "moving"});
    QTemporaryDir dir;
    const QString procedure = dir.filePath(QStringLiteral("etve.json"));
    QFile f(procedure);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "driftlab.procedure/1", "name": "ETVE on the bench", "kind": "etve",
        "sample_interval_s": 0.5, "etve": {"run_id": "E1", "duration_s": 12}})");
    f.close();
    const QString db = dir.filePath(QStringLiteral("bench.sqlite"));
    QProcess run;
    run.start(
        QStringLiteral(DRIFTLAB_CLI),
        {"run", "--procedure", procedure, "--db", db, "--rig",
         QStringLiteral("modbus://127.0.0.1:%1").arg(modulePort), "--device-map",
         DRIFTLAB_SOURCE_DIR "/resources/devices/temperature-8ch-pt100.json", "--controller",
         QStringLiteral("modbus://127.0.0.1:%1").arg(controllerPort), "--poll-interval-s", "0.2"});
    ASSERT_TRUE(run.waitForStarted());
    QThread::msleep(3500);
    module->kill();  // SIGKILL: no goodbye on the connection
    module->waitForFinished();
    QThread::msleep(3000);
    int samePort = 0;
    module = startTemperaturePeer(modulePort, &samePort);
    ASSERT_EQ(samePort, modulePort);
    ASSERT_TRUE(run.waitForFinished(60'000));
    ASSERT_EQ(run.exitCode(), 0) << run.readAllStandardError().constData();
    const qint64 campaignId = run.readAllStandardOutput().trimmed().toLongLong();

    QString error;
    auto store = db::CampaignStore::open(db, db::StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(store) << error.toStdString();
    const auto campaign = store->loadCampaign(campaignId, &error);
    ASSERT_TRUE(campaign) << error.toStdString();
    ASSERT_EQ(campaign->runs.size(), 1u);
    const SampleSeries& s = campaign->runs.front().samples;
    ASSERT_EQ(s.rowCount(), 24u);  // 12 s at 0.5 s
    const auto& t1 = s.values[std::size_t(s.columnIndex("T1"))];
    const auto& t5 = s.values[std::size_t(s.columnIndex("T5"))];  // open sensor
    const auto& position = s.values[std::size_t(s.columnIndex(kPositionColumn))];
    const auto& feed = s.values[std::size_t(s.columnIndex(kFeedColumn))];
    int hole = 0, before = 0, after = 0;
    for (std::size_t r = 2; r < s.rowCount(); ++r) {
        // The controller was never down: every row from the first second on has it.
        EXPECT_NEAR(position[r], 123.4567, 1e-4) << "row " << r;
        EXPECT_NEAR(feed[r], -2500, 0.05) << "row " << r;
        EXPECT_TRUE(std::isnan(t5[r]));
        if (std::isnan(t1[r])) {
            ++hole;
            continue;
        }
        EXPECT_DOUBLE_EQ(t1[r], 21.5);
        (hole == 0 ? before : after)++;
    }
    EXPECT_GE(before, 3);
    EXPECT_GE(hole, 3);
    EXPECT_GE(after, 3);

    QSqlQuery q(store->database());
    q.exec(QStringLiteral("SELECT level, source, message FROM event_log ORDER BY id"));
    QStringList events;
    while (q.next())
        events << q.value(0).toString() + " " + q.value(1).toString() + ": " +
                      q.value(2).toString();
    const QString moduleSource = QStringLiteral("temperature module 127.0.0.1:%1").arg(modulePort);
    const auto count = [&](const QString& prefix) {
        return std::count_if(events.begin(), events.end(),
                             [&](const QString& e) { return e.startsWith(prefix); });
    };
    EXPECT_EQ(count("error " + moduleSource), 1) << events.join('\n').toStdString();
    EXPECT_EQ(count("warning " + moduleSource + ": gap"), 1) << events.join('\n').toStdString();
    EXPECT_EQ(count("info controller: machine state: moving"), 1)
        << events.join('\n').toStdString();
    EXPECT_EQ(count("error controller"), 0) << events.join('\n').toStdString();
    module->kill();
    controller->kill();
    module->waitForFinished();
    controller->waitForFinished();
}
