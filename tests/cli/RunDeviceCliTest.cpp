// `driftlab-cli run` on real devices: Debian's pymodbus serving the
// temperature module and the controller (independent implementations of
// docs/devices.md and docs/modbus-register-map.md) on 127.0.0.1. The module
// is killed mid-run and comes back: its columns have a hole and the log a
// gap; the controller's columns never stop. With --interferometer, an
// independent stdlib peer (tests/peers/interferometer_stream.py) streams a
// reading at every planned target of a small ISO 230-2 procedure: each is
// stored with its planned cycle, target and direction.
#include <gtest/gtest.h>

#include <QSqlQuery>
#include <QTemporaryDir>
#include <QThread>
#include <cmath>

#include "core/procedures/ProcedurePlan.h"
#include "db/CampaignStore.h"
#include "tests/acquisition/DevicePeer.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

/// An ETVE procedure (`policy`: on_device_loss) on the pymodbus module and
/// controller; the module is SIGKILLed after 3.5 s and back on its port 3 s
/// later. The campaign and the event log ("level source: message").
struct OutageRun {
    std::optional<Campaign> campaign;
    QStringList events;
    QString moduleSource;
};

OutageRun runEtveThroughModuleOutage(const QString& policy) {
    OutageRun result;
    int modulePort = 0, controllerPort = 0;
    auto module = startTemperaturePeer(0, &modulePort);
    auto controller = startControllerPeer(0, &controllerPort,
                                          {"--position-mm", "123.4567", "--feed-mm-min", "-2500",
                                           "--torque-nm", "1.25", "--state", "moving"});
    result.moduleSource = QStringLiteral("temperature module 127.0.0.1:%1").arg(modulePort);
    QTemporaryDir dir;
    const QString procedure = dir.filePath(QStringLiteral("etve.json"));
    QFile f(procedure);
    EXPECT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(QStringLiteral(R"({"format": "driftlab.procedure/1", "name": "ETVE on the bench",
        "kind": "etve", "sample_interval_s": 0.5, "on_device_loss": "%1",
        "etve": {"run_id": "E1", "duration_s": 12}})")
                .arg(policy)
                .toUtf8());
    f.close();
    const QString db = dir.filePath(QStringLiteral("bench.sqlite"));
    QProcess run;
    run.start(
        QStringLiteral(DRIFTLAB_CLI),
        {"run", "--procedure", procedure, "--db", db, "--rig",
         QStringLiteral("modbus://127.0.0.1:%1").arg(modulePort), "--device-map",
         DRIFTLAB_SOURCE_DIR "/resources/devices/temperature-8ch-pt100.json", "--controller",
         QStringLiteral("modbus://127.0.0.1:%1").arg(controllerPort), "--poll-interval-s", "0.2"});
    EXPECT_TRUE(run.waitForStarted());
    QThread::msleep(3500);
    module->kill();  // SIGKILL: no goodbye on the connection
    module->waitForFinished();
    QThread::msleep(3000);
    int samePort = 0;
    module = startTemperaturePeer(modulePort, &samePort);
    EXPECT_EQ(samePort, modulePort);
    EXPECT_TRUE(run.waitForFinished(60'000));
    EXPECT_EQ(run.exitCode(), 0) << run.readAllStandardError().constData();
    const qint64 campaignId = run.readAllStandardOutput().trimmed().toLongLong();
    module->kill();
    controller->kill();
    module->waitForFinished();
    controller->waitForFinished();

    QString error;
    auto store = db::CampaignStore::open(db, db::StoreAccess::ReadOnly, &error);
    EXPECT_TRUE(store) << error.toStdString();
    if (!store) return result;
    result.campaign = store->loadCampaign(campaignId, &error);
    EXPECT_TRUE(result.campaign) << error.toStdString();
    QSqlQuery q(store->database());
    q.exec(QStringLiteral("SELECT level, source, message FROM event_log ORDER BY id"));
    while (q.next())
        result.events << q.value(0).toString() + " " + q.value(1).toString() + ": " +
                             q.value(2).toString();
    return result;
}

long countStartingWith(const QStringList& events, const QString& prefix) {
    return std::count_if(events.begin(), events.end(),
                         [&](const QString& e) { return e.startsWith(prefix); });
}

}  // namespace

TEST(RunDeviceCli, pymodbusModuleKilledMidRunLeavesAGapTheControllerKeepsLogging) {
    if (const QString why = peerUnavailable(); !why.isEmpty()) GTEST_SKIP() << why.toStdString();
    const OutageRun outage = runEtveThroughModuleOutage(QStringLiteral("continue"));
    ASSERT_TRUE(outage.campaign);
    const auto& campaign = outage.campaign;
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

    const QStringList& events = outage.events;
    const QString& moduleSource = outage.moduleSource;
    const auto count = [&](const QString& prefix) { return countStartingWith(events, prefix); };
    EXPECT_EQ(count("error " + moduleSource), 1) << events.join('\n').toStdString();
    EXPECT_EQ(count("warning " + moduleSource + ": gap"), 1) << events.join('\n').toStdString();
    EXPECT_EQ(count("info controller: machine state: moving"), 1)
        << events.join('\n').toStdString();
    EXPECT_EQ(count("error controller"), 0) << events.join('\n').toStdString();
}

TEST(RunDeviceCli, onDeviceLossPauseLogsNothingUntilTheModuleIsBack) {
    if (const QString why = peerUnavailable(); !why.isEmpty()) GTEST_SKIP() << why.toStdString();
    const OutageRun outage = runEtveThroughModuleOutage(QStringLiteral("pause"));
    ASSERT_TRUE(outage.campaign);
    const SampleSeries& s = outage.campaign->runs.front().samples;
    const auto& t1 = s.values[std::size_t(s.columnIndex("T1"))];
    // No row while the module was away, but for the rows before the loss is
    // known (a failed poll, up to the 1 s response timeout); the run's clock
    // is wall time, so the pause is a gap in time, and the run still ends at
    // its 12 s.
    double longestStep_s = 0;
    int missing = 0;
    for (std::size_t r = 2; r < s.rowCount(); ++r) {
        missing += std::isnan(t1[r]);
        longestStep_s = std::max(longestStep_s, s.time_s[r] - s.time_s[r - 1]);
    }
    EXPECT_LE(missing, 3);
    EXPECT_GE(longestStep_s, 2.0);
    EXPECT_LT(s.rowCount(), 24u);
    EXPECT_NEAR(s.time_s.back(), 12.0, 1e-9);
    EXPECT_EQ(countStartingWith(outage.events, "warning engine: paused at"), 1)
        << outage.events.join('\n').toStdString();
    EXPECT_EQ(countStartingWith(outage.events, "warning " + outage.moduleSource + ": gap"), 1)
        << outage.events.join('\n').toStdString();
}

namespace {

/// Five targets over 10…110 mm, two linear cycles: 20 readings in about 8 s.
const QByteArray kPositioningProcedure = R"({"format": "driftlab.procedure/1",
    "name": "ISO 230-2 on the bench", "kind": "iso230-2", "travel_mm": [0, 120],
    "sample_interval_s": 0.5, "positioning": {"run_id": "P1", "span_mm": [10, 110],
    "targets_per_metre": 50, "irregularity": 0, "seed": 1, "cycles": 2, "order": "linear",
    "feed_mm_min": 12000, "overrun_mm": 2, "dwell_s": 0.3}})";

/// A deviation per reading, all different, so a reading stored against the
/// wrong planned measurement shows.
double deviationOf(std::size_t k) {
    return 1.0 + 0.25 * double(k);
}

QStringList eventLog(db::CampaignStore& store) {
    QSqlQuery q(store.database());
    q.exec(QStringLiteral("SELECT level, source, message FROM event_log ORDER BY id"));
    QStringList events;
    while (q.next())
        events << q.value(0).toString() + " " + q.value(1).toString() + ": " +
                      q.value(2).toString();
    return events;
}

long countPrefix(const QStringList& events, const QString& prefix) {
    return std::count_if(events.begin(), events.end(),
                         [&](const QString& e) { return e.startsWith(prefix); });
}

/// Runs the procedure on the pymodbus module and the interferometer peer
/// (cut after `dropAfter` readings when set); checks every planned reading
/// is stored as planned and returns the event log.
QStringList runPositioningOnTheBench(std::optional<int> dropAfter, int* interferometerPort) {
    QTemporaryDir dir;
    const QString procedurePath = dir.filePath(QStringLiteral("iso230-2.json"));
    QFile f(procedurePath);
    EXPECT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(kPositioningProcedure);
    f.close();
    QString error;
    const auto procedure = procedures::loadProcedureFile(procedurePath, &error);
    EXPECT_TRUE(procedure) << error.toStdString();
    const auto planned = procedures::planRuns(*procedure).front().programme.measurements;
    EXPECT_EQ(planned.size(), 20u);

    // The peer sends each reading a little ahead of its planned time (the
    // machine's programme runs its own clock), at the target plus the
    // deviation; one stray reading off every target after the third.
    QFile readings(dir.filePath(QStringLiteral("readings.csv")));
    EXPECT_TRUE(readings.open(QIODevice::WriteOnly));
    for (std::size_t k = 0; k < planned.size(); ++k) {
        const auto& e = planned[k];
        readings.write(QStringLiteral("%1,%2,%3\n")
                           .arg(0.8 * e.time_s)
                           .arg(e.target_mm + deviationOf(k) / 1000, 0, 'f', 6)
                           .arg(deviationOf(k))
                           .toUtf8());
        if (k == 2) readings.write(QStringLiteral("%1,5.0,0.0\n").arg(0.8 * e.time_s).toUtf8());
    }
    readings.close();

    int modulePort = 0;
    auto module = startTemperaturePeer(0, &modulePort);
    QStringList peerArgs{"--scenario", "plan", "--readings", readings.fileName()};
    if (dropAfter) peerArgs << "--drop-after" << QString::number(*dropAfter);
    auto interferometer =
        startTcpPeer(QStringLiteral("interferometer_stream.py"), 0, interferometerPort, peerArgs);
    const QString db = dir.filePath(QStringLiteral("bench.sqlite"));
    QProcess run;
    run.start(QStringLiteral(DRIFTLAB_CLI),
              {"run", "--procedure", procedurePath, "--db", db, "--rig",
               QStringLiteral("modbus://127.0.0.1:%1").arg(modulePort), "--device-map",
               DRIFTLAB_SOURCE_DIR "/resources/devices/temperature-8ch-pt100.json",
               "--interferometer", QStringLiteral("tcp://127.0.0.1:%1").arg(*interferometerPort),
               "--poll-interval-s", "0.2"});
    EXPECT_TRUE(run.waitForStarted());
    EXPECT_TRUE(run.waitForFinished(120'000));
    EXPECT_EQ(run.exitCode(), 0) << run.readAllStandardError().constData();
    const QString campaignId = QString::fromUtf8(run.readAllStandardOutput().trimmed());
    module->kill();
    interferometer->kill();
    module->waitForFinished();
    interferometer->waitForFinished();

    auto store = db::CampaignStore::open(db, db::StoreAccess::ReadOnly, &error);
    EXPECT_TRUE(store) << error.toStdString();
    if (!store) return {};
    const auto campaign = store->loadCampaign(campaignId.toLongLong(), &error);
    EXPECT_TRUE(campaign) << error.toStdString();
    if (!campaign) return {};
    const QStringList events = eventLog(*store);
    const auto& stored = campaign->runs.front().positioning;
    EXPECT_EQ(stored.size(), planned.size()) << events.join('\n').toStdString();
    for (std::size_t k = 0; k < std::min(stored.size(), planned.size()); ++k) {
        EXPECT_EQ(stored[k].cycle, planned[k].cycle) << "reading " << k;
        EXPECT_DOUBLE_EQ(stored[k].target_mm, planned[k].target_mm) << "reading " << k;
        EXPECT_EQ(stored[k].direction, planned[k].direction) << "reading " << k;
        // Standard air against a standard-air reference: no correction.
        EXPECT_NEAR(stored[k].deviation_um, deviationOf(k), 1e-3) << "reading " << k;
        EXPECT_LE(stored[k].time_s, campaign->runs.front().samples.time_s.back());
    }
    // The run is an ISO 230-2 run the evaluation takes as it is.
    const CliResult iso = runCli({"iso230-2", "--db", db, "--campaign", campaignId, "--json"});
    EXPECT_EQ(iso.exitCode, 0) << iso.err.constData();
    return events;
}

}  // namespace

TEST(RunDeviceCli, interferometerReadingsAreStoredAgainstThePlannedTargets) {
    if (const QString why = peerUnavailable(); !why.isEmpty()) GTEST_SKIP() << why.toStdString();
    int port = 0;
    const QStringList events = runPositioningOnTheBench(std::nullopt, &port);
    const QString source = QStringLiteral("interferometer 127.0.0.1:%1").arg(port);
    const std::string log = events.join('\n').toStdString();
    EXPECT_EQ(countPrefix(events, "info " + source + ": environment correction: Edlén"), 1) << log;
    EXPECT_EQ(
        countPrefix(events, "warning " + source + ": reading at 5.0000 mm matches no planned"), 1)
        << log;
    EXPECT_EQ(countPrefix(events, "error " + source), 0) << log;
}

TEST(RunDeviceCli, interferometerDroppedMidRunIsOneErrorOneGapAndMatchingGoesOn) {
    if (const QString why = peerUnavailable(); !why.isEmpty()) GTEST_SKIP() << why.toStdString();
    int port = 0;
    const QStringList events = runPositioningOnTheBench(10, &port);
    const QString source = QStringLiteral("interferometer 127.0.0.1:%1").arg(port);
    const std::string log = events.join('\n').toStdString();
    EXPECT_EQ(countPrefix(events, "error " + source + ": the interferometer at"), 1) << log;
    EXPECT_EQ(countPrefix(events, "error " + source), 1) << log;
    EXPECT_EQ(countPrefix(events, "warning " + source + ": gap: no data from"), 1) << log;
    // The new stream has the same air: the correction is not logged again.
    EXPECT_EQ(countPrefix(events, "info " + source + ": environment correction:"), 1) << log;
}

TEST(RunDeviceCli, aModuleGivingFahrenheitAndKelvinIsLoggedInCelsius) {
    if (const QString why = peerUnavailable(); !why.isEmpty()) GTEST_SKIP() << why.toStdString();
    int port = 0;
    auto module = startTemperaturePeer(0, &port);
    ASSERT_GT(port, 0);
    QTemporaryDir dir;
    // The peer's registers 0 and 1 (215 and −123 counts) as a module in °F and one in K.
    const QString map = dir.filePath(QStringLiteral("module.json"));
    QFile mapFile(map);
    ASSERT_TRUE(mapFile.open(QIODevice::WriteOnly));
    mapFile.write(R"({"channels": [
        {"id": "T1", "address": 0, "kind": "input", "type": "int16", "scale": 0.1, "unit": "°F"},
        {"id": "T2", "address": 1, "kind": "input", "type": "int16", "scale": 0.1,
         "offset": 273.15, "unit": "K"}]})");
    mapFile.close();
    const QString procedure = dir.filePath(QStringLiteral("etve.json"));
    QFile procedureFile(procedure);
    ASSERT_TRUE(procedureFile.open(QIODevice::WriteOnly));
    procedureFile.write(R"({"format": "driftlab.procedure/1", "name": "ETVE in °F",
        "kind": "etve", "sample_interval_s": 0.5, "etve": {"run_id": "E1", "duration_s": 3}})");
    procedureFile.close();
    const QString db = dir.filePath(QStringLiteral("bench.sqlite"));
    const CliResult r = runCli({"run", "--procedure", procedure, "--db", db, "--rig",
                                QStringLiteral("modbus://127.0.0.1:%1").arg(port), "--device-map",
                                map, "--poll-interval-s", "0.2"});
    killPeer(*module);
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();

    QString error;
    auto store = db::CampaignStore::open(db, db::StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(store) << error.toStdString();
    const auto campaign = store->loadCampaign(r.out.trimmed().toLongLong(), &error);
    ASSERT_TRUE(campaign) << error.toStdString();
    const SampleSeries& s = campaign->runs.front().samples;
    const auto& t1 = s.values[std::size_t(s.columnIndex("T1"))];
    const auto& t2 = s.values[std::size_t(s.columnIndex("T2"))];
    int logged = 0;
    for (std::size_t row = 0; row < s.rowCount(); ++row) {
        if (std::isnan(t1[row])) continue;  // before the first poll
        ++logged;
        EXPECT_EQ(t1[row], (215 * 0.1 - 32.0) * 5.0 / 9.0) << "row " << row;  // −5.83 °C
        EXPECT_EQ(t2[row], (-123 * 0.1 + 273.15) - 273.15) << "row " << row;  // −12.3 °C
    }
    EXPECT_GE(logged, 3);
}
