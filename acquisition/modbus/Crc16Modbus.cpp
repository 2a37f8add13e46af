#include "acquisition/modbus/Crc16Modbus.h"

namespace driftlab::modbus {
namespace {

/// Folds one byte into a running CRC (bitwise: a few hundred registers per
/// push do not justify a table).
std::uint16_t feed(std::uint16_t crc, std::uint8_t byte) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc & 1) ? (crc >> 1) ^ 0xA001 : crc >> 1;
    return crc;
}

}  // namespace

std::uint16_t crc16Modbus(std::span<const std::uint8_t> bytes) {
    std::uint16_t crc = 0xFFFF;
    for (std::uint8_t byte : bytes) crc = feed(crc, byte);
    return crc;
}

std::uint16_t crc16ModbusOfRegisters(std::span<const std::uint16_t> registers) {
    std::uint16_t crc = 0xFFFF;
    for (std::uint16_t value : registers) {
        crc = feed(crc, std::uint8_t(value >> 8));
        crc = feed(crc, std::uint8_t(value & 0xFF));
    }
    return crc;
}

}  // namespace driftlab::modbus
