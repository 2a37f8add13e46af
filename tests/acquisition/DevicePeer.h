#pragma once
// The independent temperature module (tests/peers/pymodbus_temperature_module.py,
// Debian's python3-pymodbus under /usr/bin/python3) as a child process on
// 127.0.0.1, on a port the system chooses so tests run in parallel.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QFile>
#include <QProcess>
#include <memory>

namespace driftlab::test {

inline const QString kPeerPython = QStringLiteral("/usr/bin/python3");

/// Why the peer cannot run here, or empty.
inline QString peerUnavailable() {
    if (!QFile::exists(kPeerPython)) return QStringLiteral("/usr/bin/python3 missing");
    QProcess p;
    p.start(kPeerPython, {QStringLiteral("-c"), QStringLiteral("import pymodbus")});
    if (p.waitForFinished(60'000) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0)
        return {};
    return QStringLiteral("/usr/bin/python3 without pymodbus (Debian package python3-pymodbus)");
}

/// The module listening on `port` (0: a free one); its port in `*bound`.
inline std::unique_ptr<QProcess> startTemperaturePeer(int port, int* bound) {
    auto peer = std::make_unique<QProcess>();
    peer->start(kPeerPython,
                {QStringLiteral(DRIFTLAB_SOURCE_DIR "/tests/peers/pymodbus_temperature_module.py"),
                 QStringLiteral("--port"), QString::number(port)});
    EXPECT_TRUE(peer->waitForStarted());
    // Bounded: the peer prints its port once listening, or exits.
    for (int i = 0; i < 60 && !peer->canReadLine() && peer->state() == QProcess::Running; ++i)
        peer->waitForReadyRead(1000);
    *bound = peer->readLine().trimmed().toInt();
    EXPECT_GT(*bound, 0) << peer->readAllStandardError().constData();
    return peer;
}

/// Queued signals need an event loop on the test's thread; gtest_main makes none.
inline void ensureCoreApplication() {
    if (QCoreApplication::instance()) return;
    static int argc = 1;
    static char name[] = "acquisition_device_tests";
    static char* argv[] = {name, nullptr};
    // Never deleted: it must outlive every test and static.
    new QCoreApplication(argc, argv);
}

}  // namespace driftlab::test
