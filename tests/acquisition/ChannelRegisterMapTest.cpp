// The register map's decoding pinned by hand-computed vectors, its strict
// loading (errors name the key and the channel), the shipped 8-channel profile,
// and how channels are grouped into requests.
#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>
#include <cmath>

#include "acquisition/devices/ChannelRegisterMap.h"
#include "acquisition/devices/TemperatureModule.h"

using namespace driftlab::devices;

namespace {

ChannelSpec spec(ValueType type, WordOrder order = WordOrder::HighFirst, double scale = 1,
                 double offset = 0) {
    ChannelSpec c;
    c.id = QStringLiteral("c");
    c.type = type;
    c.word_order = order;
    c.scale = scale;
    c.offset = offset;
    return c;
}

double decode(const ChannelSpec& c, std::vector<std::uint16_t> words) {
    const DecodedValue v = decodeChannel(c, words);
    EXPECT_EQ(v.status, DecodeStatus::Ok);
    return v.value;
}

/// The error for a map whose only other channel is valid and whose channel 2 is `second`.
QString errorFor(const QByteArray& second) {
    const QByteArray json = R"({"channels": [
        {"id": "a", "address": 0, "kind": "input", "type": "int16", "unit": "°C"}, )" +
                            second + "]}";
    QString error;
    EXPECT_FALSE(parseChannelRegisterMap(json, &error).has_value()) << json.constData();
    return error;
}

}  // namespace

TEST(ChannelDecoding, int16NegativeAndScale) {
    // 0xFF85 = -123 as int16; 0.1 °C per count.
    EXPECT_DOUBLE_EQ(decode(spec(ValueType::Int16, {}, 0.1), {0xFF85}), -12.3);
    // The same raw with an offset: 215 · 0.1 + 273.15 = 294.65 K.
    EXPECT_DOUBLE_EQ(decode(spec(ValueType::Int16, {}, 0.1, 273.15), {215}), 294.65);
}

TEST(ChannelDecoding, uint16IsNotSignExtended) {
    // 0xFDE8 = 65000; 65000 · 0.01 − 273.15 = 376.85.
    EXPECT_NEAR(decode(spec(ValueType::UInt16, {}, 0.01, -273.15), {0xFDE8}), 376.85, 1e-9);
}

TEST(ChannelDecoding, int32InBothWordOrders) {
    // -123456 = 0xFFFE1DC0.
    EXPECT_EQ(decode(spec(ValueType::Int32, WordOrder::HighFirst), {0xFFFE, 0x1DC0}), -123456);
    EXPECT_EQ(decode(spec(ValueType::Int32, WordOrder::LowFirst), {0x1DC0, 0xFFFE}), -123456);
}

TEST(ChannelDecoding, uint32InBothWordOrders) {
    // 3000000000 = 0xB2D05E00: above INT32_MAX, so a signed decode would be negative.
    EXPECT_EQ(decode(spec(ValueType::UInt32, WordOrder::HighFirst), {0xB2D0, 0x5E00}), 3e9);
    EXPECT_EQ(decode(spec(ValueType::UInt32, WordOrder::LowFirst), {0x5E00, 0xB2D0}), 3e9);
}

TEST(ChannelDecoding, float32InBothWordOrdersWithScaleAndOffset) {
    // 21.5 = 0x41AC0000, -40 = 0xC2200000.
    EXPECT_EQ(decode(spec(ValueType::Float32, WordOrder::HighFirst), {0x41AC, 0x0000}), 21.5);
    EXPECT_EQ(decode(spec(ValueType::Float32, WordOrder::LowFirst), {0x0000, 0x41AC}), 21.5);
    EXPECT_DOUBLE_EQ(decode(spec(ValueType::Float32, WordOrder::HighFirst, 1, 273.15), {0xC220, 0}),
                     233.15);
    // The wrong order is a different, finite number: why word_order has no default.
    EXPECT_NE(decode(spec(ValueType::Float32, WordOrder::LowFirst), {0x41AC, 0x0000}), 21.5);
}

TEST(ChannelDecoding, listedRawCodesAndNonFiniteFloatsAreInvalid) {
    ChannelSpec c = spec(ValueType::Int16, {}, 0.1);
    c.invalid_raw = {0x7FFF, 0x8000};
    for (std::uint16_t code : {0x7FFF, 0x8000}) {
        const DecodedValue v = decodeChannel(c, std::vector<std::uint16_t>{code});
        EXPECT_EQ(v.status, DecodeStatus::InvalidRaw);
        EXPECT_TRUE(std::isnan(v.value));
        EXPECT_EQ(v.raw, code);
    }
    EXPECT_DOUBLE_EQ(decode(c, {0x7FFE}), 3276.6);
    const DecodedValue nan =
        decodeChannel(spec(ValueType::Float32), std::vector<std::uint16_t>{0x7FC0, 0});
    EXPECT_EQ(nan.status, DecodeStatus::InvalidRaw);
}

TEST(ChannelMapLoading, theEightChannelProfileLoads) {
    QString error;
    const auto map = loadChannelRegisterMap(
        QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/devices/temperature-8ch-pt100.json"),
        &error);
    ASSERT_TRUE(map) << qPrintable(error);
    ASSERT_EQ(map->channels.size(), 8u);
    for (int i = 0; i < 8; ++i) {
        const ChannelSpec& c = map->channels[std::size_t(i)];
        EXPECT_EQ(c.id, QStringLiteral("T%1").arg(i + 1));
        EXPECT_EQ(c.address, i);
        EXPECT_EQ(c.kind, RegisterKind::Input);
        EXPECT_EQ(c.type, ValueType::Int16);
        EXPECT_DOUBLE_EQ(c.scale, 0.1);
        EXPECT_EQ(c.unit, QStringLiteral("°C"));
        EXPECT_EQ(c.invalid_raw, (std::vector<std::uint32_t>{0x7FFF, 0x8000}));
    }
    const std::vector<ReadBlock> plan = planReads(*map);
    ASSERT_EQ(plan.size(), 1u);
    EXPECT_EQ(plan[0].count, 8);
}

TEST(ChannelMapLoading, signedInvalidCodesMeanTheSameBits) {
    QString error;
    const auto map = parseChannelRegisterMap(
        R"({"channels": [{"id": "a", "address": 3, "kind": "holding", "type": "int16",
            "unit": "°C", "invalid": [-32768, 32767]}]})",
        &error);
    ASSERT_TRUE(map) << qPrintable(error);
    EXPECT_EQ(map->channels[0].invalid_raw, (std::vector<std::uint32_t>{0x8000, 0x7FFF}));
}

TEST(ChannelMapLoading, errorsNameTheKeyAndTheChannel) {
    const struct {
        QByteArray channel;
        QString key;
    } cases[] = {
        {R"({"id": "b", "address": 1, "kind": "input", "unit": "°C"})", "\"type\": missing"},
        {R"({"id": "b", "address": 1, "kind": "input", "type": "int8", "unit": "°C"})", "\"type\""},
        {R"({"id": "b", "address": 1, "kind": "coil", "type": "int16", "unit": "°C"})", "\"kind\""},
        {R"({"id": "b", "address": -1, "kind": "input", "type": "int16", "unit": "°C"})",
         "\"address\""},
        {R"({"id": "b", "address": 1, "kind": "input", "type": "float32", "unit": "°C"})",
         "\"word_order\": missing"},
        {R"({"id": "b", "address": 1, "kind": "input", "type": "int32", "word_order": "big",
             "unit": "°C"})",
         "\"word_order\""},
        {R"({"id": "b", "address": 1, "kind": "input", "type": "int16", "unit": "°C",
             "scael": 0.1})",
         "\"scael\": unknown key"},
        {R"({"id": "b", "address": 1, "kind": "input", "type": "int16", "unit": "°C",
             "scale": 0})",
         "\"scale\""},
        {R"({"id": "b", "address": 1, "kind": "input", "type": "int16", "unit": "°C",
             "invalid": [70000]})",
         "\"invalid\""},
        {R"({"id": "b", "address": 1, "kind": "input", "type": "int16", "unit": "°C",
             "invalid": ["0xZZ"]})",
         "\"invalid\""},
        {R"({"id": "b", "address": 0, "kind": "input", "type": "int16", "unit": "°C"})",
         "\"address\": input register 0 overlaps channel \"a\""},
    };
    for (const auto& c : cases) {
        const QString error = errorFor(c.channel);
        EXPECT_TRUE(error.contains(QStringLiteral("channel 2 (\"b\")"))) << qPrintable(error);
        EXPECT_TRUE(error.contains(QStringLiteral("key ") + c.key)) << qPrintable(error);
    }
    const QString duplicate =
        errorFor(R"({"id": "a", "address": 1, "kind": "input", "type": "int16", "unit": "°C"})");
    EXPECT_TRUE(duplicate.contains(QStringLiteral("channel 2 (\"a\"): key \"id\"")))
        << qPrintable(duplicate);
    const QString unnamed = errorFor(R"({"address": 1, "kind": "input", "type": "int16"})");
    EXPECT_TRUE(unnamed.contains(QStringLiteral("channel 2: key \"id\": missing")))
        << qPrintable(unnamed);
    // A key named twice: the parser would keep the last one without a word.
    const QString twice = errorFor(
        "{\"id\": \"b\", \"address\": 1, \"kind\": \"input\", \"type\": \"int16\",\n"
        " \"unit\": \"°C\", \"scale\": 0.1,\n \"scale\": 10}");
    EXPECT_TRUE(twice.endsWith(QStringLiteral(
        "map.channels[1].scale: named twice in one object (lines 3 and 4); only one may stand")))
        << qPrintable(twice);
}

TEST(ChannelMapLoading, fahrenheitAndKelvinChannelsDecodeToCelsius) {
    QString error;
    const auto map = parseChannelRegisterMap(R"({"channels": [
        {"id": "f", "address": 0, "kind": "input", "type": "int16", "scale": 0.1, "unit": "°F"},
        {"id": "k", "address": 1, "kind": "input", "type": "int16", "scale": 0.1,
         "offset": 273.15, "unit": "K"},
        {"id": "c", "address": 2, "kind": "input", "type": "int16", "scale": 0.1, "unit": "degC"}
    ]})",
                                             &error);
    ASSERT_TRUE(map) << qPrintable(error);
    EXPECT_EQ(map->channels[0].unit, QStringLiteral("°F"));  // kept as declared
    // 0x02A8 = 680 counts = 68.0 °F = 20 °C; 0x00D7 = 215 counts = 294.65 K or
    // 21.5 °C. The conversion is exact: (°F − 32) · 5 / 9 and K − 273.15, after
    // scale and offset.
    EXPECT_EQ(decode(map->channels[0], {0x02A8}), (680 * 0.1 - 32.0) * 5.0 / 9.0);
    EXPECT_NEAR(decode(map->channels[0], {0x02A8}), 20.0, 1e-12);
    EXPECT_EQ(decode(map->channels[1], {0x00D7}), (215 * 0.1 + 273.15) - 273.15);
    EXPECT_EQ(decode(map->channels[2], {0x00D7}), 215 * 0.1);
}

TEST(ChannelMapLoading, aUnitThatIsNoTemperatureIsRefusedNamingFileChannelAndUnit) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("module.json"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(R"({"channels": [
        {"id": "T1", "address": 0, "kind": "input", "type": "int16", "unit": "°C"},
        {"id": "T2", "address": 1, "kind": "input", "type": "int16", "unit": "mV"}]})");
    file.close();
    QString error;
    EXPECT_FALSE(loadChannelRegisterMap(path, &error));
    EXPECT_EQ(error,
              path + QStringLiteral(": channel 2 (\"T2\"): key \"unit\": 'mV' is not a unit "
                                    "DriftLab reads for a temperature channel (°C, °F or K)"));
}

TEST(ReadPlanning, contiguousChannelsShareRequestsOfAtMost125Registers) {
    ChannelRegisterMap map;
    // 124 int16 channels then an int32 at 124: it does not fit the first
    // request (126 > 125) and must not be split across two.
    for (int i = 0; i < 124; ++i) {
        ChannelSpec c = spec(ValueType::Int16);
        c.kind = RegisterKind::Holding;
        c.address = i;
        map.channels.push_back(c);
    }
    ChannelSpec wide = spec(ValueType::Int32);
    wide.kind = RegisterKind::Holding;
    wide.address = 124;
    map.channels.push_back(wide);
    // An input register at the same address, and one after a gap.
    ChannelSpec input = spec(ValueType::Int16);
    input.address = 0;
    map.channels.push_back(input);
    input.address = 10;
    map.channels.push_back(input);

    const std::vector<ReadBlock> plan = planReads(map);
    ASSERT_EQ(plan.size(), 4u);
    EXPECT_EQ(plan[0].kind, RegisterKind::Holding);
    EXPECT_EQ(plan[0].address, 0);
    EXPECT_EQ(plan[0].count, 124);
    EXPECT_EQ(plan[1].address, 124);
    EXPECT_EQ(plan[1].count, 2);
    EXPECT_EQ(plan[2].kind, RegisterKind::Input);
    EXPECT_EQ(plan[2].count, 1);
    EXPECT_EQ(plan[3].address, 10);
}
