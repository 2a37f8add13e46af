// driftlab-cli compensate --push, pushes and controller-sim as a test engineer
// and a script use them: a push from the store recorded in its history, a
// failed push that exits non-zero with its reason and is recorded too, the
// steps in --json, usage errors before any work, and the simulated controller
// served in the foreground until SIGTERM.
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include "acquisition/sim/SimulatedController.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

/// The example campaign imported into dir/store.sqlite; returns its id.
QString importExample(const QTemporaryDir& dir) {
    const CliResult r =
        runCli({"import", exampleBundlePath(), "--db", dir.filePath("store.sqlite")});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return QString::fromUtf8(r.out.trimmed());
}

std::unique_ptr<sim::SimulatedController> controller(driftlab::MachineState state) {
    sim::SimulatedControllerOptions options;
    options.state = state;
    auto sim = std::make_unique<sim::SimulatedController>(options);
    QString error;
    EXPECT_TRUE(sim->start(&error)) << qPrintable(error);
    return sim;
}

QJsonArray pushes(const QString& db) {
    const CliResult r = runCli({"pushes", "--db", db, "--json"});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return json(r)["pushes"].toArray();
}

}  // namespace

TEST(PushCli, pushFromTheStoreIsAppliedAndRecordedInItsHistory) {
    QTemporaryDir dir;
    const QString db = dir.filePath("store.sqlite");
    const QString id = importExample(dir);
    auto sim = controller(driftlab::MachineState::Idle);
    const CliResult r = runCli({"compensate", "--db", db, "--campaign", id, "--run", "S1",
                                "--spacing", "35", "--push", sim->url(), "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject pushed = json(r)["push"].toObject();
    EXPECT_EQ(pushed["result"].toString(), QStringLiteral("applied"));
    QStringList steps;
    for (const QJsonValue& step : pushed["steps"].toArray()) {
        steps << step["step"].toString();
        EXPECT_TRUE(step["ok"].toBool()) << qPrintable(step["detail"].toString());
    }
    EXPECT_EQ(steps, QStringList({"connect", "identify", "read_active", "check", "abort_leftover",
                                  "stage", "commit", "await_ack", "read_back"}));
    EXPECT_EQ(sim->activeTable().points(), 21);
    EXPECT_EQ(sim->activeTable().checksum(), pushed["checksum"].toInt());

    const QJsonArray history = pushes(db);
    ASSERT_EQ(history.size(), 1);
    const QJsonObject row = history[0].toObject();
    EXPECT_EQ(row["result"].toString(), QStringLiteral("applied"));
    EXPECT_EQ(row["campaign"].toInteger(), id.toLongLong());
    EXPECT_EQ(row["run"].toString(), QStringLiteral("S1"));
    EXPECT_EQ(row["controller"].toString(), sim->url());
    EXPECT_EQ(row["version"].toInt(), 1);
    EXPECT_EQ(row["points"].toInt(), 21);
    EXPECT_EQ(row["checksum"].toInt(), pushed["checksum"].toInt());
    EXPECT_EQ(row["table"].toObject()["correction_plus_um"].toArray().size(), 21);
    EXPECT_EQ(row["steps"].toArray().size(), 9);
}

TEST(PushCli, machineThatKeepsCuttingFailsThePushWithOneLineAndIsRecorded) {
    QTemporaryDir dir;
    const QString db = dir.filePath("store.sqlite");
    const QString id = importExample(dir);
    auto sim = controller(driftlab::MachineState::Cutting);
    const CliResult r = runCli({"compensate", "--db", db, "--campaign", id, "--push", sim->url(),
                                "--timeout-s", "0.2", "--json"});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(reason(r.err),
              QByteArray("driftlab-cli compensate: push failed: table v1 not applied within 0.2 s "
                         "(machine cutting, commit status: staged, waiting for a safe state); "
                         "aborted, the previous table (v0) is intact"));
    // The JSON still says what happened at each step.
    const QJsonObject pushed = json(r)["push"].toObject();
    EXPECT_EQ(pushed["result"].toString(), QStringLiteral("failed"));
    EXPECT_TRUE(pushed["previous_intact"].toBool());
    EXPECT_EQ(sim->activeTable().version(), 0);
    const QJsonArray history = pushes(db);
    ASSERT_EQ(history.size(), 1);
    EXPECT_EQ(history[0]["result"].toString(), QStringLiteral("failed"));
    EXPECT_TRUE(history[0]["message"].toString().contains(QStringLiteral("not applied within")));
}

TEST(PushCli, pushFromABundleIsRecordedOnlyInAGivenHistory) {
    QTemporaryDir dir;
    importExample(dir);
    const QString db = dir.filePath("store.sqlite");
    auto sim = controller(driftlab::MachineState::Idle);
    const CliResult plain = runCli({"compensate", exampleBundlePath(), "--push", sim->url()});
    ASSERT_EQ(plain.exitCode, 0) << plain.err.constData();
    EXPECT_TRUE(plain.out.contains("push to " + sim->url().toUtf8() + ": applied\n"))
        << plain.out.constData();
    EXPECT_EQ(pushes(db).size(), 0);
    const CliResult recorded =
        runCli({"compensate", exampleBundlePath(), "--push", sim->url(), "--history", db});
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.constData();
    const QJsonArray history = pushes(db);
    ASSERT_EQ(history.size(), 1);
    EXPECT_TRUE(history[0]["campaign"].isNull());
    EXPECT_EQ(history[0]["version"].toInt(), 2);
}

TEST(PushCli, badPushOptionsAreUsageErrorsBeforeAnyWork) {
    const auto refused = [](QStringList args, const QByteArray& why) {
        const CliResult r = runCli(QStringList{"compensate", exampleBundlePath()} + args);
        EXPECT_EQ(r.exitCode, 2) << r.err.constData();
        EXPECT_EQ(reason(r.err), "driftlab-cli compensate: " + why);
    };
    refused({"--push", "modbus://plc"},
            "--push: 'modbus://plc': no port (expected modbus://HOST:PORT[/UNIT])");
    refused({"--format", "csv", "--out", "x.csv", "--timeout-s", "3"},
            "--timeout-s goes with --push");
    refused({}, "give --format F --out FILE, --push modbus://HOST:PORT, or both");
    refused({"--format", "csv", "--push", "modbus://127.0.0.1:1502"},
            "--format and --out go together");
}

TEST(PushCli, controllerSimServesUntilSigtermAndTakesAPush) {
    QProcess sim;
    sim.start(QStringLiteral(DRIFTLAB_CLI), {"controller-sim", "--json"});
    ASSERT_TRUE(sim.waitForStarted());
    while (!sim.canReadLine() && sim.state() == QProcess::Running) sim.waitForReadyRead(1000);
    const QJsonObject started = QJsonDocument::fromJson(sim.readLine()).object();
    ASSERT_GT(started["port"].toInt(), 0) << sim.readAllStandardError().constData();
    const CliResult r =
        runCli({"compensate", exampleBundlePath(), "--push", started["url"].toString()});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    sim.terminate();  // SIGTERM
    ASSERT_TRUE(sim.waitForFinished(30'000));
    EXPECT_EQ(sim.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(sim.exitCode(), 0);
    EXPECT_EQ(sim.readAllStandardError(),
              QByteArray("controller-sim: stopped (SIGTERM), 1 table(s) applied\n"));
}
