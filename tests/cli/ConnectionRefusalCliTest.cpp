// Bad inputs for reaching a device or a store, as a user types them, through
// the real driftlab-cli: each is refused with its exit code and one line
// naming the option, the URL part or the file and key, and why, and nothing
// is written. Name lookups use .invalid names, which fail without a network
// (RFC 6761).
#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>

#include "tests/cli/CliRunner.h"
#include "tests/core/BundleTestSupport.h"

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
