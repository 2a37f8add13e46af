// Bad inputs for reaching a device or a store, as a user types them, through
// the real driftlab-cli: each is refused with its exit code and one line
// naming the option, the URL part or the file and key, and why, and nothing
// is written. Name lookups use .invalid names, which fail without a network
// (RFC 6761).
#include <gtest/gtest.h>

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "acquisition/modbus/ModbusLink.h"
#include "acquisition/modbus/ModbusUrl.h"
#include "tests/acquisition/DevicePeer.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

const QByteArray kEtveProcedure = R"({"format": "driftlab.procedure/1", "name": "ETVE",
    "kind": "etve", "sample_interval_s": 0.5, "etve": {"run_id": "E1", "duration_s": 2}})";

QString writeIn(const QTemporaryDir& dir, const QString& name, const QByteArray& content) {
    const QString path = dir.filePath(name);
    writeFile(path, content);
    return path;
}

/// Whether this host can listen on ::1 (a container may have no IPv6 loopback).
bool hasIpv6Loopback() {
    const int s = ::socket(AF_INET6, SOCK_STREAM, 0);
    if (s < 0) return false;
    sockaddr_in6 address{};
    address.sin6_family = AF_INET6;
    address.sin6_addr = in6addr_loopback;
    const bool ok = ::bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
    ::close(s);
    return ok;
}

}  // namespace

TEST(ConnectionRefusalCli, aDeviceMapUnitThatIsNoTemperatureIsRefusedBeforeTheStoreIsMade) {
    QTemporaryDir dir;
    QByteArray map = readFile(DRIFTLAB_SOURCE_DIR "/resources/devices/temperature-8ch-pt100.json");
    map.replace("\"°C\"", "\"mV\"");
    const QString mapPath = writeIn(dir, QStringLiteral("module.json"), map);
    const QString db = dir.filePath(QStringLiteral("bench.sqlite"));
    // No module listens on port 9: the map is refused before any connection.
    const CliResult r =
        runCli({"run", "--procedure", writeIn(dir, QStringLiteral("etve.json"), kEtveProcedure),
                "--db", db, "--rig", "modbus://127.0.0.1:9", "--device-map", mapPath});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(QString::fromUtf8(reason(r.err)),
              QStringLiteral("driftlab-cli run: --device-map: %1: channel 1 (\"T1\"): key "
                             "\"unit\": 'mV' is not a unit DriftLab reads for a temperature "
                             "channel (°C, °F or K)")
                  .arg(mapPath));
    EXPECT_FALSE(QFile::exists(db));
}

TEST(ConnectionRefusalCli, controllerSimRefusesAHostThatIsNoAddressAndListensOnNothing) {
    const CliResult r = runCli({"controller-sim", "--host", "bogus.invalid", "--port", "0"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(reason(r.err).startsWith(
        "driftlab-cli controller-sim: --host: 'bogus.invalid' is neither an IP address nor a "
        "host name that resolves ("))
        << r.err.constData();
    EXPECT_TRUE(r.out.isEmpty()) << r.out.constData();  // no "serving … on" line
}

TEST(ConnectionRefusalCli, controllerSimOnIpv6PrintsABracketedUrlThatReadsBack) {
    if (!hasIpv6Loopback()) GTEST_SKIP() << "no IPv6 loopback (::1) on this host";
    QProcess sim;
    sim.start(QStringLiteral(DRIFTLAB_CLI), {"controller-sim", "--host", "::1", "--port", "0"});
    ASSERT_TRUE(sim.waitForStarted());
    const QString line = peerLine(sim);
    const QString prefix = QStringLiteral("controller-sim: serving DriftLab's register map on ");
    ASSERT_TRUE(line.startsWith(prefix + QStringLiteral("modbus://[::1]:")))
        << qPrintable(line) << sim.readAllStandardError().constData();
    const QString printed = line.mid(prefix.size()).section(QLatin1Char(' '), 0, 0);
    QString error;
    const auto url = modbus::parseModbusUrl(printed, &error);
    ASSERT_TRUE(url) << qPrintable(error);
    EXPECT_EQ(url->host, QStringLiteral("::1"));
    EXPECT_EQ(url->toString(), printed);
    // The URL reaches the controller it names: register 0 holds the map's magic.
    modbus::ModbusLink link(*url, 5.0);
    ASSERT_TRUE(link.connect(&error)) << qPrintable(error);
    std::vector<std::uint16_t> words;
    ASSERT_TRUE(link.readRegisters(0, 2, words, &error)) << qPrintable(error);
    EXPECT_EQ(words[0], 0x4446);
    link.close();
    sim.terminate();
    ASSERT_TRUE(sim.waitForFinished(30'000));
    EXPECT_EQ(sim.exitCode(), 0);
}

TEST(ConnectionRefusalCli, aModbusHostThatDoesNotResolveIsSaidSoNotConnectionRefused) {
    const CliResult r =
        runCli({"compensate", exampleBundlePath(), "--push", "modbus://no-such-host.invalid:502"});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(reason(r.err).startsWith(
        "driftlab-cli compensate: push failed: no-such-host.invalid:502: cannot connect: host "
        "'no-such-host.invalid' could not be resolved ("))
        << r.err.constData();
    EXPECT_TRUE(reason(r.err).endsWith("; nothing written")) << r.err.constData();
    EXPECT_FALSE(r.err.contains("Connection refused")) << r.err.constData();
}

TEST(ConnectionRefusalCli, aModbusPortOutOfRangeOrNotANumberNamesThePortAndTheRange) {
    for (const char* port : {"70000", "abc", "0"}) {
        const QString url = QStringLiteral("modbus://127.0.0.1:%1").arg(QLatin1String(port));
        const CliResult r = runCli({"compensate", exampleBundlePath(), "--push", url});
        EXPECT_EQ(r.exitCode, 2) << port;
        EXPECT_EQ(QString::fromUtf8(reason(r.err)),
                  QStringLiteral("driftlab-cli compensate: --push: '%1': port '%2' is not a "
                                 "number from 1 to 65535 (expected modbus://HOST:PORT[/UNIT])")
                      .arg(url, QLatin1String(port)));
        EXPECT_TRUE(r.out.isEmpty()) << port << r.out.constData();
    }
}

TEST(ConnectionRefusalCli, aPostgresqlPortOutOfRangeNamesTheUrlWithoutItsPassword) {
    QTemporaryDir dir;
    const CliResult imported =
        runCli({"import", exampleBundlePath(), "--db", "postgresql://user@127.0.0.1:99999/db"});
    EXPECT_EQ(imported.exitCode, 2);
    EXPECT_EQ(QString::fromUtf8(reason(imported.err)),
              QStringLiteral("driftlab-cli import: --db: postgresql://user@127.0.0.1:99999/db: "
                             "port '99999' is not a number from 1 to 65535 (expected "
                             "postgresql://USER@HOST[:PORT]/DB)"));
    // A run logs into its spool first: a refused URL leaves no spool behind.
    const QString spool = dir.filePath(QStringLiteral("spool.sqlite"));
    const CliResult run =
        runCli({"run", "--procedure", writeIn(dir, QStringLiteral("etve.json"), kEtveProcedure),
                "--db", "postgresql://user:secret@127.0.0.1:abc/db", "--spool", spool});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_EQ(QString::fromUtf8(reason(run.err)),
              QStringLiteral("driftlab-cli run: --db: postgresql://user@127.0.0.1:abc/db: "
                             "port 'abc' is not a number from 1 to 65535 (expected "
                             "postgresql://USER@HOST[:PORT]/DB)"));
    EXPECT_FALSE(run.err.contains("secret")) << run.err.constData();
    EXPECT_FALSE(QFile::exists(spool));
}
