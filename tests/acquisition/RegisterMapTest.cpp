// The compensation register map as integrators read it in
// docs/modbus-register-map.md: exact registers of a small table (golden
// values, the checksum computed independently with pymodbus's computeCRC),
// refusals of what the registers cannot carry, and the modbus:// URL.
#include <gtest/gtest.h>

#include <string_view>

#include "acquisition/modbus/Crc16Modbus.h"
#include "acquisition/modbus/ModbusUrl.h"
#include "acquisition/push/CompensationRegisterMap.h"

using namespace driftlab;
using namespace driftlab::push;

namespace {

/// -40, 10, 60 mm; -1.5, 0.25 and 12.34 µm (+); -2, 0, 1 µm (−).
compensation::CompensationTable goldenTable(bool bidirectional) {
    compensation::CompensationTable table;
    table.position_mm = {-40, 10, 60};
    table.correction_plus_um = {-1.5, 0.25, 12.34};
    table.correction_minus_um =
        bidirectional ? std::vector<double>{-2, 0, 1} : table.correction_plus_um;
    table.bidirectional = bidirectional;
    return table;
}

}  // namespace

TEST(Crc16Modbus, standardCheckValueOf123456789Is0x4B37) {
    const std::string_view check = "123456789";
    EXPECT_EQ(
        modbus::crc16Modbus({reinterpret_cast<const std::uint8_t*>(check.data()), check.size()}),
        0x4B37);
    // The same bytes as registers, high byte first.
    const std::uint16_t registers[] = {0x3132, 0x3334, 0x3536, 0x3738};
    const std::uint8_t tail = '9';
    std::vector<std::uint8_t> bytes{'1', '2', '3', '4', '5', '6', '7', '8'};
    EXPECT_EQ(modbus::crc16ModbusOfRegisters(registers), modbus::crc16Modbus(bytes));
    bytes.push_back(tail);
    EXPECT_EQ(modbus::crc16Modbus(bytes), 0x4B37);
}

TEST(CompensationRegisterMap, unidirectionalTableGivesTheDocumentedRegisters) {
    const EncodeResult encoded = encodeTable(goldenTable(false), 7, 256);
    ASSERT_TRUE(encoded.ok()) << qPrintable(encoded.error);
    // version, points, start -40000 µm (high word first), spacing 50000 µm,
    // flags, CRC-16/MODBUS (0xC46D from pymodbus.utilities.computeCRC, unswapped).
    const std::array<std::uint16_t, kHeaderCount> header{7,      3,      0xFFFF, 0x63C0,
                                                         0x0000, 0xC350, 0,      0xC46D};
    EXPECT_EQ(encoded.image.header, header);
    // 0.1 µm, rounded half away from zero: -15, 3, 123.
    EXPECT_EQ(encoded.image.plus, (std::vector<std::uint16_t>{0xFFF1, 0x0003, 0x007B}));
    EXPECT_TRUE(encoded.image.minus.empty());
}

TEST(CompensationRegisterMap, bidirectionalTableCarriesTheMinusColumnAndFlag) {
    const EncodeResult encoded = encodeTable(goldenTable(true), 7, 256);
    ASSERT_TRUE(encoded.ok()) << qPrintable(encoded.error);
    EXPECT_EQ(encoded.image.header[6], kFlagBidirectional);
    EXPECT_EQ(encoded.image.minus, (std::vector<std::uint16_t>{0xFFEC, 0x0000, 0x000A}));
    EXPECT_EQ(encoded.image.checksum(), 0x32FE);
}

TEST(CompensationRegisterMap, decodingGivesTheTableBackOnTheRegisterGrid) {
    const auto table = goldenTable(true);
    const auto decoded = decodeTable(encodeTable(table, 9, 256).image);
    EXPECT_EQ(decoded.position_mm, table.position_mm);
    EXPECT_EQ(decoded.correction_plus_um, (std::vector<double>{-1.5, 0.3, 12.3}));
    EXPECT_EQ(decoded.correction_minus_um, table.correction_minus_um);
    EXPECT_TRUE(decoded.bidirectional);
}

TEST(CompensationRegisterMap, valueBeyondInt16IsRefusedNamingThePoint) {
    auto table = goldenTable(false);
    table.correction_plus_um[2] = table.correction_minus_um[2] = 3276.8;
    EXPECT_EQ(encodeTable(table, 1, 256).error,
              QStringLiteral("point 2 at 60.0000 mm: correction 3276.800 µm does not fit the "
                             "register (int16 in 0.1 µm: -3276.8 to 3276.7 µm)"));
    table.correction_plus_um[2] = table.correction_minus_um[2] = 3276.7;
    EXPECT_TRUE(encodeTable(table, 1, 256).ok());
    table.bidirectional = true;
    table.correction_minus_um[0] = -3300;
    EXPECT_TRUE(
        encodeTable(table, 1, 256)
            .error.startsWith(QStringLiteral("point 0 at -40.0000 mm: correction - -3300.000 µm")));
}

TEST(CompensationRegisterMap, tableOverCapacityOrOffTheGridIsRefused) {
    auto table = goldenTable(false);
    EXPECT_EQ(encodeTable(table, 1, 2).error,
              QStringLiteral("3 points: the controller takes 2 to 2 points per table"));
    table.position_mm[1] = 10.002;  // 2 µm off an equally spaced table
    EXPECT_EQ(encodeTable(table, 1, 256).error,
              QStringLiteral("point 1 at 10.0020 mm is off the equally spaced µm grid (10.0000 "
                             "mm expected at a spacing of 50000 µm)"));
    EXPECT_FALSE(encodeTable(goldenTable(false), 0, 256).ok()) << "version 0 means no table";
}

TEST(ModbusUrl, hostPortAndUnitAreParsedAndMistakesNamed) {
    QString error;
    const auto url = modbus::parseModbusUrl(QStringLiteral("modbus://10.0.0.5:1502/3"), &error);
    ASSERT_TRUE(url) << qPrintable(error);
    EXPECT_EQ(url->host, QStringLiteral("10.0.0.5"));
    EXPECT_EQ(url->port, 1502);
    EXPECT_EQ(url->unit, 3);
    EXPECT_EQ(url->toString(), QStringLiteral("modbus://10.0.0.5:1502/3"));
    EXPECT_EQ(modbus::parseModbusUrl(QStringLiteral("modbus://plc:502"), &error)->unit, 1);
    EXPECT_FALSE(modbus::parseModbusUrl(QStringLiteral("modbus://plc"), &error));
    EXPECT_EQ(error,
              QStringLiteral("'modbus://plc': no port (expected modbus://HOST:PORT[/UNIT])"));
    EXPECT_FALSE(modbus::parseModbusUrl(QStringLiteral("tcp://plc:502"), &error));
    EXPECT_FALSE(modbus::parseModbusUrl(QStringLiteral("modbus://plc:502/300"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("unit '300'"))) << qPrintable(error);
}

TEST(ModbusUrl, aBadPortOrHostIsNamedAndAnIpv6AddressComesBackInBrackets) {
    const auto refused = [](const char* text) {
        QString error;
        EXPECT_FALSE(modbus::parseModbusUrl(QString::fromUtf8(text), &error)) << text;
        return error;
    };
    EXPECT_EQ(refused("modbus://127.0.0.1:70000"),
              QStringLiteral("'modbus://127.0.0.1:70000': port '70000' is not a number from 1 to "
                             "65535 (expected modbus://HOST:PORT[/UNIT])"));
    EXPECT_EQ(refused("modbus://127.0.0.1:abc"),
              QStringLiteral("'modbus://127.0.0.1:abc': port 'abc' is not a number from 1 to "
                             "65535 (expected modbus://HOST:PORT[/UNIT])"));
    EXPECT_TRUE(refused("modbus://127.0.0.1:0").contains(QStringLiteral("port '0' is not")));
    EXPECT_TRUE(refused("modbus://::1:502")
                    .contains(QStringLiteral("an IPv6 address goes in brackets, e.g. [::1]:502")));
    EXPECT_TRUE(
        refused("modbus://pl c:502")
            .contains(QStringLiteral("host 'pl c' is neither a host name nor an IP address")));
    QString error;
    const auto v6 = modbus::parseModbusUrl(QStringLiteral("modbus://[::1]:1502"), &error);
    ASSERT_TRUE(v6) << qPrintable(error);
    EXPECT_EQ(v6->host, QStringLiteral("::1"));
    EXPECT_EQ(v6->port, 1502);
    EXPECT_EQ(v6->toString(), QStringLiteral("modbus://[::1]:1502"));
}
