#pragma once
// CRC-16/MODBUS (poly 0xA001 reflected, init 0xFFFF, no final xor): the check
// value of "123456789" is 0x4B37. The push checksums a table with it
// (docs/modbus-register-map.md, register 107).

#include <cstddef>
#include <cstdint>
#include <span>

namespace driftlab::modbus {

/// The CRC of `bytes`, as a number (not byte-swapped as in an RTU frame).
std::uint16_t crc16Modbus(std::span<const std::uint8_t> bytes);

/// The CRC of registers taken as two bytes each, high byte first.
std::uint16_t crc16ModbusOfRegisters(std::span<const std::uint16_t> registers);

}  // namespace driftlab::modbus
