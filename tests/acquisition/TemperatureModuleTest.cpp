// DriftLab's temperature module driver against an independent Modbus server
// (Debian's python3-pymodbus): the 8-channel profile's values and codes, and
// 32-bit values in both word orders, are read as the peer's script states them.
#include <gtest/gtest.h>

#include <cmath>

#include "acquisition/devices/TemperatureModule.h"
#include "tests/acquisition/DevicePeer.h"

using namespace driftlab;
using namespace driftlab::devices;

TEST(TemperatureModulePeer, profileChannelsReadInOneRequestWithScaleAndOpenShortCodes) {
    if (const QString why = test::peerUnavailable(); !why.isEmpty())
        GTEST_SKIP() << qPrintable(why);
    int port = 0;
    auto peer = test::startTemperaturePeer(0, &port);
    ASSERT_GT(port, 0);
    QString error;
    auto map = loadChannelRegisterMap(
        QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/devices/temperature-8ch-pt100.json"),
        &error);
    ASSERT_TRUE(map) << qPrintable(error);

    TemperatureModule module(*map, test::localPeer(port));
    ASSERT_TRUE(module.connect(&error)) << qPrintable(error);
    const auto reading = module.read(&error);
    ASSERT_TRUE(reading) << qPrintable(error);
    EXPECT_EQ(module.requests(), 1);
    EXPECT_TRUE(reading->warning.isEmpty()) << qPrintable(reading->warning);
    EXPECT_TRUE(reading->time_utc.isValid());

    // The peer's PROFILE_DEGC; channels 5 and 6 carry the open and short codes.
    const double expected_degC[] = {21.5, -12.3, 0.0, 100.0, NAN, NAN, 25.3, 3276.6};
    ASSERT_EQ(reading->values.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i) {
        if (i == 4 || i == 5) {
            EXPECT_EQ(reading->status[i], ChannelStatus::InvalidRaw) << i;
            EXPECT_TRUE(std::isnan(reading->values[i])) << i;
        } else {
            EXPECT_EQ(reading->status[i], ChannelStatus::Ok) << i;
            EXPECT_NEAR(reading->values[i], expected_degC[i], 1e-9) << i;
        }
    }
    EXPECT_EQ(reading->raw[4], 0x7FFFu);
    EXPECT_EQ(reading->raw[5], 0x8000u);
    peer->kill();
    peer->waitForFinished();
}

TEST(TemperatureModulePeer, channelsDeclaredInFahrenheitAndKelvinAreReadInCelsius) {
    if (const QString why = test::peerUnavailable(); !why.isEmpty())
        GTEST_SKIP() << qPrintable(why);
    int port = 0;
    auto peer = test::startTemperaturePeer(0, &port);
    ASSERT_GT(port, 0);
    // The peer's registers 0 and 1 hold 215 and −123 counts: read here as a
    // module that gives °F, and one that gives K (offset 273.15).
    QString error;
    const auto map = parseChannelRegisterMap(R"({"channels": [
        {"id": "f", "address": 0, "kind": "input", "type": "int16", "scale": 0.1, "unit": "°F"},
        {"id": "k", "address": 1, "kind": "input", "type": "int16", "scale": 0.1,
         "offset": 273.15, "unit": "K"}]})",
                                             &error);
    ASSERT_TRUE(map) << qPrintable(error);
    TemperatureModule module(*map, test::localPeer(port));
    ASSERT_TRUE(module.connect(&error)) << qPrintable(error);
    const auto reading = module.read(&error);
    ASSERT_TRUE(reading) << qPrintable(error);
    ASSERT_EQ(reading->values.size(), 2u);
    EXPECT_EQ(reading->values[0], (215 * 0.1 - 32.0) * 5.0 / 9.0);
    EXPECT_EQ(reading->values[1], (-123 * 0.1 + 273.15) - 273.15);
    EXPECT_NEAR(reading->values[1], -12.3, 1e-9);
    peer->kill();
    peer->waitForFinished();
}

TEST(TemperatureModulePeer, thirtyTwoBitValuesInBothWordOrdersMatchThePeer) {
    if (const QString why = test::peerUnavailable(); !why.isEmpty())
        GTEST_SKIP() << qPrintable(why);
    int port = 0;
    auto peer = test::startTemperaturePeer(0, &port);
    ASSERT_GT(port, 0);
    QString error;
    // Every channel in °C: the types and word orders are under test, not the unit.
    const auto map = parseChannelRegisterMap(R"({"channels": [
        {"id": "f_hi", "address": 100, "kind": "holding", "type": "float32", "word_order": "high-first", "unit": "°C"},
        {"id": "f_lo", "address": 102, "kind": "holding", "type": "float32", "word_order": "low-first", "unit": "°C"},
        {"id": "i32", "address": 104, "kind": "holding", "type": "int32", "word_order": "high-first", "unit": "°C", "scale": 0.001},
        {"id": "u32", "address": 106, "kind": "holding", "type": "uint32", "word_order": "low-first", "unit": "°C"},
        {"id": "u16", "address": 108, "kind": "holding", "type": "uint16", "unit": "°C", "scale": 0.01, "offset": -273.15}
    ]})",
                                             &error);
    ASSERT_TRUE(map) << qPrintable(error);
    TemperatureModule module(*map, test::localPeer(port));
    ASSERT_TRUE(module.connect(&error)) << qPrintable(error);
    const auto reading = module.read(&error);
    ASSERT_TRUE(reading) << qPrintable(error);
    EXPECT_EQ(module.requests(), 1);  // 100…108 are contiguous
    EXPECT_EQ(reading->values[0], 21.5);
    EXPECT_EQ(reading->values[1], 21.5);
    EXPECT_NEAR(reading->values[2], -123.456, 1e-9);
    EXPECT_EQ(reading->values[3], 3e9);
    EXPECT_NEAR(reading->values[4], 376.85, 1e-9);
    for (ChannelStatus s : reading->status) EXPECT_EQ(s, ChannelStatus::Ok);
    peer->kill();
    peer->waitForFinished();
}

TEST(TemperatureModulePeer, registersTheModuleLacksAreNotReadWhileOthersAre) {
    if (const QString why = test::peerUnavailable(); !why.isEmpty())
        GTEST_SKIP() << qPrintable(why);
    int port = 0;
    auto peer = test::startTemperaturePeer(0, &port);
    ASSERT_GT(port, 0);
    QString error;
    // Input register 5000 is beyond the peer's block: a Modbus exception.
    const auto map = parseChannelRegisterMap(R"({"channels": [
        {"id": "T1", "address": 0, "kind": "input", "type": "int16", "unit": "°C", "scale": 0.1},
        {"id": "far", "address": 5000, "kind": "input", "type": "int16", "unit": "°C"}
    ]})",
                                             &error);
    ASSERT_TRUE(map) << qPrintable(error);
    TemperatureModule module(*map, test::localPeer(port));
    ASSERT_TRUE(module.connect(&error)) << qPrintable(error);
    const auto reading = module.read(&error);
    ASSERT_TRUE(reading) << qPrintable(error);
    EXPECT_EQ(reading->status[0], ChannelStatus::Ok);
    EXPECT_DOUBLE_EQ(reading->values[0], 21.5);
    EXPECT_EQ(reading->status[1], ChannelStatus::NotRead);
    EXPECT_TRUE(reading->warning.contains(QStringLiteral("5000"))) << qPrintable(reading->warning);
    EXPECT_TRUE(module.isConnected());
    peer->kill();
    peer->waitForFinished();
}
