// Modbus RTU: the modbus-rtu:// address, and the temperature module over a
// serial line — two ptys joined by tests/peers/pty_bridge.py, Debian's
// pymodbus serial RTU server (an independent implementation) on one end,
// DriftLab's libmodbus link on the other. A bad CRC is forged by hand.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>
#include <QSignalSpy>
#include <cmath>
#include <thread>

#include "acquisition/devices/TemperatureDevice.h"
#include "acquisition/modbus/Crc16Modbus.h"
#include "acquisition/modbus/ModbusLink.h"
#include "tests/acquisition/DevicePeer.h"
#include "tests/support/SignalWait.h"

using namespace driftlab;
using namespace driftlab::devices;

namespace {

modbus::ModbusUrl rtuUrl(const QString& device) {
    QString error;
    const auto url = modbus::parseModbusUrl(
        QStringLiteral("modbus-rtu://%1?baud=19200&parity=N&data=8&stop=1&unit=1").arg(device),
        &error);
    EXPECT_TRUE(url) << qPrintable(error);
    return url.value_or(modbus::ModbusUrl{});
}

QString parseError(const char* text) {
    QString error;
    EXPECT_FALSE(modbus::parseModbusUrl(QString::fromUtf8(text), &error)) << text;
    return error;
}

}  // namespace

TEST(ModbusRtuUrl, settingsAndTheirDefaults) {
    QString error;
    const auto url = modbus::parseModbusUrl(
        QStringLiteral("modbus-rtu:///dev/ttyUSB0?baud=9600&parity=o&data=8&stop=2&unit=17"),
        &error);
    ASSERT_TRUE(url) << qPrintable(error);
    EXPECT_TRUE(url->isRtu());
    EXPECT_EQ(url->serial.device, QStringLiteral("/dev/ttyUSB0"));
    EXPECT_EQ(url->serial.baud, 9600);
    EXPECT_EQ(url->serial.parity, 'O');
    EXPECT_EQ(url->serial.stop_bits, 2);
    EXPECT_EQ(url->unit, 17);
    EXPECT_EQ(url->endpoint(), QStringLiteral("/dev/ttyUSB0 9600 8O2 unit 17"));
    // The defaults: the Modbus serial line specification's 19200 8E1, unit 1.
    const auto plain = modbus::parseModbusUrl(QStringLiteral("modbus-rtu:///dev/ttyS1"), &error);
    ASSERT_TRUE(plain) << qPrintable(error);
    EXPECT_EQ(plain->toString(),
              QStringLiteral("modbus-rtu:///dev/ttyS1?baud=19200&parity=E&data=8&stop=1&unit=1"));
    // TCP addresses are what they were.
    EXPECT_FALSE(modbus::parseModbusUrl(QStringLiteral("modbus://plc:502"), &error)->isRtu());
}

TEST(ModbusRtuUrl, mistakesNameThePartAtFault) {
    EXPECT_TRUE(parseError("modbus-rtu://dev/ttyUSB0").contains(QStringLiteral("three slashes")));
    EXPECT_TRUE(parseError("modbus-rtu://").contains(QStringLiteral("no serial device")));
    EXPECT_TRUE(parseError("modbus-rtu:///dev/ttyUSB0?parity=X")
                    .contains(QStringLiteral("parity 'X' is not N, E or O")));
    EXPECT_TRUE(
        parseError("modbus-rtu:///dev/ttyUSB0?baud=fast").contains(QStringLiteral("baud 'fast'")));
    EXPECT_TRUE(
        parseError("modbus-rtu:///dev/ttyUSB0?data=7").contains(QStringLiteral("data '7'")));
    EXPECT_TRUE(
        parseError("modbus-rtu:///dev/ttyUSB0?stop=3").contains(QStringLiteral("stop '3'")));
    EXPECT_TRUE(
        parseError("modbus-rtu:///dev/ttyUSB0?unit=0").contains(QStringLiteral("unit '0'")));
    EXPECT_TRUE(parseError("modbus-rtu:///dev/ttyUSB0?speed=9600")
                    .contains(QStringLiteral("unknown setting 'speed'")));
    EXPECT_TRUE(parseError("modbus-rtu:///dev/ttyUSB0?baud=9600&baud=19200")
                    .contains(QStringLiteral("'baud' given twice")));
    EXPECT_TRUE(parseError("serial:///dev/ttyUSB0").contains(QStringLiteral("modbus-rtu://")));
}

TEST(ModbusRtuPeer, eightChannelsReadOverRtuWithScaleAndOpenShortCodes) {
    if (const QString why = test::peerUnavailable(); !why.isEmpty())
        GTEST_SKIP() << qPrintable(why);
    test::PtyBridge bridge = test::startPtyBridge();
    auto peer = test::startRtuTemperaturePeer(bridge.peers);
    TemperatureModule module(test::temperatureProfile(), rtuUrl(bridge.ours));
    QString error;
    ASSERT_TRUE(module.connect(&error)) << qPrintable(error);
    const auto reading = module.read(&error);
    ASSERT_TRUE(reading) << qPrintable(error);
    EXPECT_EQ(module.requests(), 1);
    const double expected_degC[] = {21.5, -12.3, 0.0, 100.0, NAN, NAN, 25.3, 3276.6};
    ASSERT_EQ(reading->values.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i) {
        if (i == 4 || i == 5) {
            EXPECT_EQ(reading->status[i], ChannelStatus::InvalidRaw) << i;
        } else {
            EXPECT_EQ(reading->status[i], ChannelStatus::Ok) << i;
            EXPECT_NEAR(reading->values[i], expected_degC[i], 1e-9) << i;
        }
    }
    EXPECT_EQ(reading->raw[4], 0x7FFFu);
    EXPECT_EQ(reading->raw[5], 0x8000u);
    test::killPeer(*peer);
    test::killPeer(*bridge.process);
}

TEST(ModbusRtuLink, anAnswerWithABadCrcIsAClearErrorAndClosesTheLink) {
    if (const QString why = test::peerUnavailable(); !why.isEmpty())
        GTEST_SKIP() << qPrintable(why);
    test::PtyBridge bridge = test::startPtyBridge();
    // Our own forged device on the peer's end: answers one request with the
    // right bytes and a CRC off by one.
    const QByteArray path = bridge.peers.toLocal8Bit();
    const int fd = ::open(path.constData(), O_RDWR | O_NOCTTY);
    ASSERT_GE(fd, 0);
    termios raw{};
    tcgetattr(fd, &raw);
    cfmakeraw(&raw);
    tcsetattr(fd, TCSANOW, &raw);
    std::thread device([fd] {
        std::uint8_t request[8];
        std::size_t got = 0;
        for (int i = 0; i < 100 && got < sizeof request; ++i) {
            pollfd p{fd, POLLIN, 0};
            if (::poll(&p, 1, 100) > 0) {
                const ssize_t n = ::read(fd, request + got, sizeof request - got);
                if (n > 0) got += std::size_t(n);
            }
        }
        // Unit 1, function 4, 2 bytes: 0x00D7 (21.5 °C); CRC sent low byte first.
        std::uint8_t answer[] = {0x01, 0x04, 0x02, 0x00, 0xD7, 0, 0};
        const std::uint16_t crc =
            std::uint16_t(modbus::crc16Modbus(std::span<const std::uint8_t>(answer, 5)) + 1);
        answer[5] = std::uint8_t(crc & 0xFF);
        answer[6] = std::uint8_t(crc >> 8);
        if (got == sizeof request) (void)!::write(fd, answer, sizeof answer);
    });
    modbus::ModbusLink link(rtuUrl(bridge.ours), 2.0);
    QString error;
    ASSERT_TRUE(link.connect(&error)) << qPrintable(error);
    std::vector<std::uint16_t> words;
    EXPECT_FALSE(link.readInputRegisters(0, 1, words, &error));
    device.join();
    ::close(fd);
    EXPECT_TRUE(error.contains(QStringLiteral("CRC"), Qt::CaseInsensitive)) << qPrintable(error);
    EXPECT_TRUE(error.contains(bridge.ours)) << qPrintable(error);
    EXPECT_FALSE(link.isConnected());
    test::killPeer(*bridge.process);
}

TEST(ModbusRtuDevice, peerStoppedMidRun_oneTimeoutErrorAGapAndReconnect) {
    if (const QString why = test::peerUnavailable(); !why.isEmpty())
        GTEST_SKIP() << qPrintable(why);
    test::PtyBridge bridge = test::startPtyBridge();
    auto peer = test::startRtuTemperaturePeer(bridge.peers);
    DeviceWorkerOptions options;
    options.poll_interval_s = 0.05;
    options.backoff_initial_s = 0.05;
    options.backoff_max_s = 0.4;
    options.response_timeout_s = 0.3;
    TemperatureDevice device(test::temperatureProfile(), rtuUrl(bridge.ours), options);
    QSignalSpy readings(&device, &TemperatureDevice::readingReady);
    QSignalSpy errors(&device, &TemperatureDevice::errorOccurred);
    QSignalSpy gaps(&device, &TemperatureDevice::gap);
    QSignalSpy attempts(&device, &TemperatureDevice::attemptFailed);
    device.start();
    ASSERT_TRUE(test::waitFor(readings, 3));
    EXPECT_EQ(errors.count(), 0);

    test::killPeer(*peer);  // the line stays; nobody answers on it
    ASSERT_TRUE(test::waitFor(errors, 1));
    ASSERT_TRUE(test::waitFor(attempts, 3));
    EXPECT_EQ(errors.count(), 1);
    const QString message = errors.at(0).at(0).toString();
    EXPECT_TRUE(message.contains(bridge.ours)) << qPrintable(message);
    EXPECT_TRUE(message.contains(QStringLiteral("timed out"))) << qPrintable(message);
    const int before = int(readings.count());

    auto second = test::startRtuTemperaturePeer(bridge.peers);
    ASSERT_TRUE(test::waitFor(gaps, 1));
    ASSERT_TRUE(test::waitFor(readings, before + 3));
    EXPECT_EQ(errors.count(), 1);
    EXPECT_EQ(gaps.count(), 1);
    for (const auto& args : readings) {
        const auto r = args.at(0).value<TemperatureReading>();
        EXPECT_DOUBLE_EQ(r.values[0], 21.5);
        EXPECT_DOUBLE_EQ(r.values[7], 3276.6);
    }
    EXPECT_TRUE(device.stopAndWait(5000));
    test::killPeer(*second);
    test::killPeer(*bridge.process);
}
