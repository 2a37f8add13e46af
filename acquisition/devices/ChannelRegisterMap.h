#pragma once
// A device's measuring channels as Modbus registers (docs/devices.md): where
// each channel sits, how its words make a raw number, and how the raw number
// becomes an engineering value (value = raw · scale + offset, then into °C
// from the unit the map declares: core/domain/Units.h). Loading is
// strict: a map that would be read wrongly is refused with the key and the
// channel named, because a mis-scaled temperature looks plausible.

#include <QByteArray>
#include <QString>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/domain/Units.h"

namespace driftlab::devices {

enum class RegisterKind { Holding, Input };
enum class ValueType { Int16, UInt16, Int32, UInt32, Float32 };
/// For 32-bit types: which register carries the high 16 bits.
enum class WordOrder { HighFirst, LowFirst };

struct ChannelSpec {
    QString id;
    int address = 0;
    RegisterKind kind = RegisterKind::Input;
    ValueType type = ValueType::Int16;
    WordOrder word_order = WordOrder::HighFirst;
    double scale = 1.0;
    double offset = 0.0;
    QString unit;  ///< as the map declares it
    /// From `unit` to °C, applied after scale and offset: the module is read
    /// for temperatures, which DriftLab logs in °C whatever the module gives.
    UnitConversion to_celsius;
    /// Raw bit patterns (16 or 32 bits, unsigned) that mean "no value", e.g.
    /// 0x7FFF for an open sensor: decoded, they would be a believable number.
    std::vector<std::uint32_t> invalid_raw;

    /// 1 for 16-bit types, 2 for 32-bit ones.
    int registerCount() const;
};

struct ChannelRegisterMap {
    QString name;
    QString description;
    std::vector<ChannelSpec> channels;
};

/// The map in `json`, or nullopt with `error` naming the key and the channel.
std::optional<ChannelRegisterMap> parseChannelRegisterMap(const QByteArray& json, QString* error);
/// The map in the file at `path` (errors also name the file).
std::optional<ChannelRegisterMap> loadChannelRegisterMap(const QString& path, QString* error);

enum class DecodeStatus { Ok, InvalidRaw };

struct DecodedValue {
    double value = 0.0;  ///< engineering value in °C; NaN unless status is Ok
    DecodeStatus status = DecodeStatus::Ok;
    std::uint32_t raw = 0;  ///< the raw bit pattern (high word in bits 16–31)
};

/// The raw bit pattern of `words` (registerCount() of them, in register order).
std::uint32_t rawBits(const ChannelSpec& channel, std::span<const std::uint16_t> words);
/// The channel's value from its registers; a listed invalid raw value, or a
/// float32 that is NaN or infinite, is InvalidRaw.
DecodedValue decodeChannel(const ChannelSpec& channel, std::span<const std::uint16_t> words);

QString toString(RegisterKind kind);
QString toString(ValueType type);

}  // namespace driftlab::devices
