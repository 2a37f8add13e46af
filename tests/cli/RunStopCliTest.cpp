// A long run on real devices can always be stopped: paused on a lost device
// (a module that never answered, or one SIGKILLed mid-run), SIGINT and
// SIGTERM each end `driftlab-cli run` within 2 s, the run kept as
// `interrupted` and resumable. A device that never answers fails the run
// after its connect timeout instead of pausing it for ever; a run logged on
// one rig is not resumed on another.
#include <gtest/gtest.h>

#include <QElapsedTimer>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QThread>
#include <csignal>

#include "tests/acquisition/DevicePeer.h"
#include "tests/acquisition/LoggedRunSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

const QString kDeviceMap =
    QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/devices/temperature-8ch-pt100.json");

/// An ETVE procedure of `duration_s` that pauses on a lost device.
QString writeEtve(const QTemporaryDir& dir, int duration_s) {
    const QString path = dir.filePath(QStringLiteral("etve.json"));
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(QStringLiteral(R"({"format": "driftlab.procedure/1", "name": "ETVE on the bench",
        "kind": "etve", "sample_interval_s": 0.5, "on_device_loss": "pause",
        "etve": {"run_id": "E1", "duration_s": %1}})")
                .arg(duration_s)
                .toUtf8());
    return path;
}

int freePort() {
    QTcpServer probe;
    EXPECT_TRUE(probe.listen(QHostAddress::LocalHost, 0));
    return probe.serverPort();
}

QStringList runArgs(const QString& procedure, const QString& db, int port) {
    return {"run",
            "--procedure",
            procedure,
            "--db",
            db,
            "--rig",
            QStringLiteral("modbus://127.0.0.1:%1").arg(port),
            "--device-map",
            kDeviceMap,
            "--poll-interval-s",
            "0.2"};
}

/// Reads `run`'s stderr until it holds `text`; false when it ends first or after 60 s.
bool waitForStderr(QProcess& run, QByteArray& err, const char* text) {
    if (!run.waitForStarted()) return false;
    QElapsedTimer waited;
    waited.start();
    while (!err.contains(text)) {
        if (run.state() != QProcess::Running || waited.elapsed() > 60'000) return false;
        run.waitForReadyRead(200);
        err += run.readAllStandardError();
    }
    return true;
}

/// Sends `signal` to the run and returns how long it took to exit (ms), -1 if not within 10 s.
qint64 stopWith(QProcess& run, int signal) {
    QElapsedTimer sinceSignal;
    ::kill(pid_t(run.processId()), signal);
    sinceSignal.start();
    if (!run.waitForFinished(10'000)) return -1;
    return sinceSignal.elapsed();
}

}  // namespace

TEST(RunStopCli, sigintEndsARunPausedOnAModuleThatNeverAnswered) {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("bench.sqlite"));
    const QString procedure = writeEtve(dir, 600);
    QProcess run;
    run.start(QStringLiteral(DRIFTLAB_CLI), runArgs(procedure, db, freePort()));
    QByteArray err;
    ASSERT_TRUE(waitForStderr(run, err, "paused)")) << err.constData();
    const qint64 took_ms = stopWith(run, SIGINT);
    ASSERT_GE(took_ms, 0) << "still running 10 s after SIGINT";
    EXPECT_LT(took_ms, 2000);
    err += run.readAllStandardError();
    EXPECT_EQ(run.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(run.exitCode(), 3) << err.constData();
    EXPECT_TRUE(err.contains("marked interrupted")) << err.constData();
    EXPECT_EQ(runStatuses(db), QStringList{QStringLiteral("E1=interrupted")});

    // Resumed on the simulated rig it would get simulated readings: refused.
    const CliResult onSim =
        runCli({"run", "--procedure", procedure, "--db", db, "--rig", "sim", "--resume", "1"});
    EXPECT_EQ(onSim.exitCode, 1) << onSim.err.constData();
    EXPECT_TRUE(
        reason(onSim.err).startsWith("driftlab-cli run: run 1 (E1) cannot be resumed on simulated "
                                     "rig (seed 1): it was logged on "
                                     "temperature module temperature-8ch-pt100 at 127.0.0.1:"))
        << onSim.err.constData();
    EXPECT_EQ(runStatuses(db), QStringList{QStringLiteral("E1=interrupted")});
}

TEST(RunStopCli, sigtermEndsARunPausedOnALostModuleAndTheRunResumes) {
    if (const QString why = peerUnavailable(); !why.isEmpty()) GTEST_SKIP() << why.toStdString();
    QTemporaryDir dir;
    const QString procedure = writeEtve(dir, 6);
    const QString db = dir.filePath(QStringLiteral("bench.sqlite"));
    int port = 0;
    auto module = startTemperaturePeer(0, &port);
    QProcess run;
    run.start(QStringLiteral(DRIFTLAB_CLI), runArgs(procedure, db, port));
    QByteArray err;
    ASSERT_TRUE(waitForStderr(run, err, "running)")) << err.constData();
    QThread::msleep(1500);
    killPeer(*module);
    ASSERT_TRUE(waitForStderr(run, err, "paused)")) << err.constData();
    const qint64 took_ms = stopWith(run, SIGTERM);
    ASSERT_GE(took_ms, 0) << "still running 10 s after SIGTERM";
    EXPECT_LT(took_ms, 2000);
    EXPECT_EQ(run.exitCode(), 3) << err.constData();
    ASSERT_EQ(runStatuses(db), QStringList{QStringLiteral("E1=interrupted")});

    int samePort = 0;
    module = startTemperaturePeer(port, &samePort);
    ASSERT_EQ(samePort, port);
    // The first run of a fresh store has id 1.
    const CliResult resumed = runCli(runArgs(procedure, db, port) << "--resume"
                                                                  << "1");
    killPeer(*module);
    EXPECT_EQ(resumed.exitCode, 0) << resumed.err.constData();
    EXPECT_EQ(runStatuses(db), QStringList{QStringLiteral("E1=complete")});
}

TEST(RunStopCli, aModuleThatNeverAnswersFailsTheRunAfterTheConnectTimeout) {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("bench.sqlite"));
    const int port = freePort();
    const CliResult r = runCli(runArgs(writeEtve(dir, 600), db, port) << "--connect-timeout-s"
                                                                      << "1.5");
    EXPECT_EQ(r.exitCode, 1) << r.err.constData();
    EXPECT_TRUE(reason(r.err).contains(
        QStringLiteral("temperature module 127.0.0.1:%1: no reading within 1.5 s of the start")
            .arg(port)
            .toUtf8()))
        << r.err.constData();
    EXPECT_EQ(runStatuses(db), QStringList{QStringLiteral("E1=interrupted")});
}
