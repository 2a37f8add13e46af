#pragma once
// The independent peers (tests/peers/: the temperature module and the
// controller, Debian's python3-pymodbus under /usr/bin/python3) as child
// processes on 127.0.0.1, on a port the system chooses so tests run in
// parallel; and the pty bridge the RTU tests put between a peer and DriftLab.
#include <gtest/gtest.h>

#include <QFile>
#include <QProcess>
#include <memory>

#include "acquisition/devices/ChannelRegisterMap.h"
#include "acquisition/modbus/ModbusUrl.h"

namespace driftlab::test {

/// The temperature peer's register profile, as a user installs it.
inline devices::ChannelRegisterMap temperatureProfile() {
    QString error;
    auto map = devices::loadChannelRegisterMap(
        QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/devices/temperature-8ch-pt100.json"),
        &error);
    EXPECT_TRUE(map) << qPrintable(error);
    return map.value_or(devices::ChannelRegisterMap{});
}

/// A Modbus TCP peer on this host, unit 1.
inline modbus::ModbusUrl localPeer(int port) {
    return {QStringLiteral("127.0.0.1"), port, 1};
}

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

/// The next line `process` prints (bounded: 60 s, or until it exits).
inline QString peerLine(QProcess& process) {
    for (int i = 0; i < 60 && !process.canReadLine() && process.state() == QProcess::Running; ++i)
        process.waitForReadyRead(1000);
    return QString::fromUtf8(process.readLine().trimmed());
}

/// tests/peers/`script` with `args`, started by /usr/bin/python3.
inline std::unique_ptr<QProcess> startPeerScript(const QString& script, const QStringList& args) {
    auto peer = std::make_unique<QProcess>();
    peer->start(kPeerPython,
                QStringList{QStringLiteral(DRIFTLAB_SOURCE_DIR "/tests/peers/") + script} + args);
    EXPECT_TRUE(peer->waitForStarted());
    return peer;
}

/// A TCP peer listening on `port` (0: a free one); its port in `*bound`.
inline std::unique_ptr<QProcess> startTcpPeer(const QString& script, int port, int* bound,
                                              const QStringList& args = {}) {
    auto peer = startPeerScript(
        script, QStringList{QStringLiteral("--port"), QString::number(port)} + args);
    // The peer prints its port once listening, or exits.
    *bound = peerLine(*peer).toInt();
    EXPECT_GT(*bound, 0) << peer->readAllStandardError().constData();
    return peer;
}

/// The module listening on `port` (0: a free one); its port in `*bound`.
inline std::unique_ptr<QProcess> startTemperaturePeer(int port, int* bound) {
    return startTcpPeer(QStringLiteral("pymodbus_temperature_module.py"), port, bound);
}

/// The independent controller of the register map, serving `args` (axis state).
inline std::unique_ptr<QProcess> startControllerPeer(int port, int* bound,
                                                     const QStringList& args = {}) {
    return startTcpPeer(QStringLiteral("pymodbus_controller.py"), port, bound, args);
}

/// Two ptys joined back to back (tests/peers/pty_bridge.py): their paths.
struct PtyBridge {
    std::unique_ptr<QProcess> process;
    QString ours;   ///< the end DriftLab opens
    QString peers;  ///< the end the peer serves
};
inline PtyBridge startPtyBridge() {
    PtyBridge bridge;
    bridge.process = startPeerScript(QStringLiteral("pty_bridge.py"), {});
    bridge.ours = peerLine(*bridge.process);
    bridge.peers = peerLine(*bridge.process);
    EXPECT_TRUE(bridge.ours.startsWith(QLatin1String("/dev/")))
        << bridge.process->readAllStandardError().constData();
    return bridge;
}

/// The temperature module serving Modbus RTU on `device` (19200 8N1, unit 1);
/// returns once the device is open.
inline std::unique_ptr<QProcess> startRtuTemperaturePeer(const QString& device) {
    auto peer = startPeerScript(QStringLiteral("pymodbus_temperature_module.py"),
                                {QStringLiteral("--rtu"), device});
    EXPECT_EQ(peerLine(*peer), QStringLiteral("ready")) << peer->readAllStandardError().constData();
    return peer;
}

/// Kills (SIGKILL: no goodbye) and reaps a peer.
inline void killPeer(QProcess& peer) {
    peer.kill();
    peer.waitForFinished();
}

}  // namespace driftlab::test
