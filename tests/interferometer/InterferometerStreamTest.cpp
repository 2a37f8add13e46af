// The TCP reader against a real peer: tests/peers/interferometer_stream.py, an
// interferometer written in Python from docs/interferometer.md, on 127.0.0.1
// at a port it picks itself (so tests run in parallel).
#include <gtest/gtest.h>

#include <QFile>
#include <QProcess>
#include <vector>

#include "acquisition/devices/InterferometerStream.h"

using namespace driftlab;

namespace {

const QString kPython = QStringLiteral("/usr/bin/python3");

struct Peer {
    QProcess process;
    quint16 port = 0;

    explicit Peer(const QString& scenario) {
        process.start(kPython,
                      {QStringLiteral(DRIFTLAB_SOURCE_DIR "/tests/peers/interferometer_stream.py"),
                       QStringLiteral("--scenario"), scenario});
        if (!process.waitForStarted()) return;
        while (!process.canReadLine() && process.state() == QProcess::Running)
            process.waitForReadyRead(1000);
        port = quint16(process.readLine().trimmed().toUInt());
    }
    ~Peer() {
        if (!process.waitForFinished(30'000)) process.kill();
        process.waitForFinished();
    }
};

struct Read {
    devices::InterferometerStreamResult result;
    std::vector<interferometer::CorrectedReading> readings;
};

Read readFrom(const Peer& peer) {
    Read read;
    devices::InterferometerStreamOptions options;
    options.port = peer.port;
    read.result = devices::readInterferometerStream(
        options, [&](const interferometer::CorrectedReading& r) { read.readings.push_back(r); });
    return read;
}

}  // namespace

class InterferometerStreamTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!QFile::exists(kPython)) GTEST_SKIP() << "/usr/bin/python3 missing";
    }
};

TEST_F(InterferometerStreamTest, readsAndCorrectsACompleteStreamWithCompensationOff) {
    Peer peer(QStringLiteral("good"));
    ASSERT_GT(peer.port, 0) << peer.process.readAllStandardError().constData();
    const Read read = readFrom(peer);
    EXPECT_TRUE(read.result.complete) << read.result.error.toStdString();
    EXPECT_TRUE(read.result.error.isEmpty());
    ASSERT_EQ(read.readings.size(), 4u);
    EXPECT_EQ(read.result.readings, 4);

    // The peer's lines, corrected with the air of the env line before each
    // (reference=vacuum: n0 = 1, so L_true = L_reading / n).
    const double n1 =
        interferometer::edlenRefractiveIndex(interferometer::AirState{20.4, 100'800, 42.0});
    const double n2 =
        interferometer::edlenRefractiveIndex(interferometer::AirState{20.6, 100'810, 42.5});
    const struct {
        int line;
        double position_mm, deviation_um, n;
    } expected[] = {
        {4, 0.0, 0.0, n1}, {5, 100.0, 1.25, n1}, {6, 200.0, 2.5, n1}, {8, 300.0, 3.75, n2}};
    for (std::size_t i = 0; i < 4; ++i) {
        const interferometer::CorrectedReading& r = read.readings[i];
        EXPECT_EQ(r.line, expected[i].line);
        EXPECT_EQ(r.reading.position_mm, expected[i].position_mm);
        EXPECT_NEAR(r.position_mm, expected[i].position_mm / expected[i].n, 1e-12);
        EXPECT_NEAR(r.deviation_um,
                    expected[i].deviation_um +
                        expected[i].position_mm * 1000.0 * (1.0 / expected[i].n - 1.0),
                    1e-7);
        EXPECT_TRUE(r.correction.applied);
    }
    EXPECT_NEAR(read.readings[3].correction.correction_ppm, (1.0 / n2 - 1.0) * 1e6, 1e-9);
    // About −270 ppm: a vacuum wavelength used in air.
    EXPECT_NEAR(read.readings[3].correction.correction_ppm, -270.0, 2.0);
    EXPECT_TRUE(
        read.result.correction.startsWith(QStringLiteral("Edlén, 20.6 °C, 100.8 kPa, 43 %RH: −")))
        << read.result.correction.toStdString();
}

TEST_F(InterferometerStreamTest, compensatedStreamIsPassedThroughAndSaysSo) {
    Peer peer(QStringLiteral("compensated"));
    ASSERT_GT(peer.port, 0);
    const Read read = readFrom(peer);
    EXPECT_TRUE(read.result.complete) << read.result.error.toStdString();
    ASSERT_EQ(read.readings.size(), 4u);
    EXPECT_EQ(read.readings[3].position_mm, 300.0);
    EXPECT_EQ(read.readings[3].deviation_um, 3.75);
    EXPECT_EQ(read.result.correction,
              QStringLiteral("none: the interferometer compensated itself"));
}

TEST_F(InterferometerStreamTest, badLineEndsTheReadNamingLineAndFieldReadingsBeforeKept) {
    Peer peer(QStringLiteral("bad-line"));
    ASSERT_GT(peer.port, 0);
    const Read read = readFrom(peer);
    EXPECT_FALSE(read.result.complete);
    EXPECT_EQ(read.result.errorLine, 7);
    EXPECT_EQ(read.result.error.toStdString(),
              "line 7, pressure_Pa: air pressure 1008.1 Pa is outside 60000…120000 Pa "
              "(hPa? DriftLab expects Pa)");
    ASSERT_EQ(read.readings.size(), 3u);
    EXPECT_EQ(read.readings[2].reading.position_mm, 200.0);
}

TEST_F(InterferometerStreamTest, peerClosingMidStreamIsACleanErrorReadingsBeforeKept) {
    Peer peer(QStringLiteral("close-mid"));
    ASSERT_GT(peer.port, 0);
    const Read read = readFrom(peer);
    EXPECT_FALSE(read.result.complete);
    EXPECT_EQ(read.result.errorLine, 0);
    EXPECT_EQ(read.result.error,
              QStringLiteral("the interferometer at 127.0.0.1:%1 closed the connection after "
                             "line 5 without an 'end' line (a cut-off line '1.5,200.' dropped); "
                             "the 2 reading(s) before are kept")
                  .arg(peer.port));
    ASSERT_EQ(read.readings.size(), 2u);
    EXPECT_EQ(read.readings[1].reading.position_mm, 100.0);
}

TEST(InterferometerStream, nobodyListeningIsAConnectError) {
    // A port that was free a moment ago: bind 0 in the peer is not needed here,
    // a closed port on 127.0.0.1 refuses at once.
    devices::InterferometerStreamOptions options;
    options.port = 1;  // privileged, never listened on by tests
    const auto result =
        devices::readInterferometerStream(options, [](const interferometer::CorrectedReading&) {});
    EXPECT_FALSE(result.complete);
    EXPECT_TRUE(
        result.error.startsWith(QStringLiteral("cannot connect to the interferometer at "
                                               "127.0.0.1:1")))
        << result.error.toStdString();
}
