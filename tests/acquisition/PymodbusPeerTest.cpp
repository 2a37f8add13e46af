// The independent peer: a controller written in Python against the register
// map document with Debian's python3-pymodbus (tests/peers/pymodbus_controller.py)
// takes a push from driftlab-cli, and Debian's mbpoll, a third Modbus
// implementation, reads the active table back; it must hold the exported CSV's
// corrections in 0.1 µm.
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <cmath>

#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab::test;

namespace {

const QString kPython = QStringLiteral("/usr/bin/python3");
const QString kMbpoll = QStringLiteral("/usr/bin/mbpoll");

bool pythonHasPymodbus() {
    QProcess p;
    p.start(kPython, {QStringLiteral("-c"), QStringLiteral("import pymodbus")});
    return p.waitForFinished(60'000) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
}

/// Holding registers [reference, reference + count) read by mbpoll (references from 1).
std::vector<int> mbpollRead(int port, int reference, int count) {
    QProcess p;
    p.start(kMbpoll, {"-m", "tcp", "-t", "4", "-r", QString::number(reference), "-c",
                      QString::number(count), "-1", "-p", QString::number(port), "127.0.0.1"});
    EXPECT_TRUE(p.waitForFinished(60'000));
    EXPECT_EQ(p.exitCode(), 0) << p.readAllStandardError().constData();
    // "[1101]: 	65520 (-16)": the signed reading in brackets when it differs.
    static const QRegularExpression line(QStringLiteral(R"(^\[(\d+)\]:\s+(\d+)(?: \((-?\d+)\))?)"),
                                         QRegularExpression::MultilineOption);
    std::vector<int> values;
    auto it = line.globalMatch(QString::fromUtf8(p.readAllStandardOutput()));
    while (it.hasNext()) {
        const auto m = it.next();
        values.push_back(m.captured(3).isEmpty() ? m.captured(2).toInt() : m.captured(3).toInt());
    }
    return values;
}

}  // namespace

TEST(PymodbusPeer, tablePushedByTheCliIsReadBackByMbpollEqualToTheCsv) {
    if (!QFile::exists(kPython) || !pythonHasPymodbus())
        GTEST_SKIP() << "/usr/bin/python3 without pymodbus (Debian package python3-pymodbus)";
    if (!QFile::exists(kMbpoll)) GTEST_SKIP() << "/usr/bin/mbpoll missing (Debian package mbpoll)";

    QProcess peer;
    peer.start(kPython, {QStringLiteral(DRIFTLAB_SOURCE_DIR "/tests/peers/pymodbus_controller.py"),
                         QStringLiteral("--port"), QStringLiteral("0")});
    ASSERT_TRUE(peer.waitForStarted());
    while (!peer.canReadLine() && peer.state() == QProcess::Running) peer.waitForReadyRead(1000);
    const int port = peer.readLine().trimmed().toInt();
    ASSERT_GT(port, 0) << peer.readAllStandardError().constData();

    QTemporaryDir dir;
    const QString csv = dir.filePath(QStringLiteral("x.csv"));
    const CliResult r =
        runCli({"compensate", exampleBundlePath(), "--spacing", "35", "--format", "csv", "--out",
                csv, "--push", QStringLiteral("modbus://127.0.0.1:%1").arg(port), "--json"});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject pushed = QJsonDocument::fromJson(r.out).object()["push"].toObject();
    EXPECT_EQ(pushed["result"].toString(), QStringLiteral("applied"));

    QList<QByteArray> rows = readFile(csv).trimmed().split('\n');
    rows.removeFirst();
    const std::vector<int> header = mbpollRead(port, 1001, 8);
    ASSERT_EQ(header.size(), 8u);
    EXPECT_EQ(header[0], pushed["version"].toInt());
    EXPECT_EQ(header[1], rows.size());
    EXPECT_EQ(uint16_t(header[7]), pushed["checksum"].toInt());
    const std::vector<int> plus = mbpollRead(port, 1101, int(rows.size()));
    ASSERT_EQ(plus.size(), std::size_t(rows.size()));
    for (int i = 0; i < rows.size(); ++i) {
        const double correction_um = rows[i].split(',')[1].toDouble();
        EXPECT_EQ(plus[i], std::lround(correction_um * 10)) << rows[i].constData();
    }
    peer.kill();
    peer.waitForFinished();
}
