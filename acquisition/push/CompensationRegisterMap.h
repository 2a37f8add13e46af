#pragma once
// The compensation part of DriftLab's Modbus register map
// (docs/modbus-register-map.md): register addresses, and a table as the
// registers that carry it. Corrections are int16 in 0.1 µm, positions int32
// in µm high word first, the checksum CRC-16/MODBUS.

#include <QString>
#include <array>
#include <cstdint>
#include <vector>

#include "core/compensation/CompensationTable.h"
#include "core/domain/MachineState.h"

namespace driftlab::push {

/// Block 0: identity and machine state, written by the controller.
namespace reg {
inline constexpr int kMagic = 0;
inline constexpr int kMapVersion = 1;
inline constexpr int kMachineState = 2;
inline constexpr int kCapacity = 3;
inline constexpr int kActiveVersion = 4;
inline constexpr int kCommitStatus = 5;
inline constexpr int kAckVersion = 6;
inline constexpr int kPreviousVersion = 7;
/// The axis state the controller reports (AxisStateRegisters.h): a flag, then
/// position (int32, 2), feed (int32, 2), torque (int16).
inline constexpr int kAxisReport = 8;
inline constexpr int kAxisPosition = 9;
inline constexpr int kAxisFeed = 11;
inline constexpr int kAxisTorque = 13;
inline constexpr int kIdentityCount = 16;
/// Block 1: the staged table, written by DriftLab; block 2: the active table.
inline constexpr int kStagedHeader = 100;
inline constexpr int kCommand = 108;
inline constexpr int kStagedData = 200;
inline constexpr int kActiveHeader = 1000;
inline constexpr int kActiveData = 1100;
/// Block 3: the live offset (2000…2005).
inline constexpr int kLiveFirst = 2000;
inline constexpr int kLiveCount = 6;
}  // namespace reg

inline constexpr std::uint16_t kMagicValue = 0x4446;  // "DF"
inline constexpr std::uint16_t kMapVersionValue = 1;
inline constexpr int kMaxCapacity = 256;
/// Header registers: version, points, start (2), spacing (2), flags, checksum.
inline constexpr int kHeaderCount = 8;
inline constexpr std::uint16_t kFlagBidirectional = 1;

enum class CommitStatus : std::uint16_t {
    Nothing = 0,
    Staged = 1,
    Applied = 2,
    Refused = 3,
    ChecksumMismatch = 4,
    Aborted = 5,
    RolledBack = 6,
};
enum class Command : std::uint16_t { Commit = 1, Abort = 2, RollBack = 3 };

QString describe(CommitStatus status);

/// A table as registers: the header (version … checksum) and the data columns.
struct TableImage {
    std::array<std::uint16_t, kHeaderCount> header{};
    std::vector<std::uint16_t> plus;   ///< one int16 per point, 0.1 µm
    std::vector<std::uint16_t> minus;  ///< empty unless bidirectional

    std::uint16_t version() const { return header[0]; }
    int points() const { return header[1]; }
    std::int32_t start_um() const;
    std::int32_t spacing_um() const;
    bool bidirectional() const { return header[6] & kFlagBidirectional; }
    std::uint16_t checksum() const { return header[7]; }
    /// CRC-16/MODBUS of header registers 0…6 then plus, then minus.
    std::uint16_t computeChecksum() const;
    bool operator==(const TableImage&) const = default;
};

struct EncodeResult {
    QString error;  ///< empty on success; names the point and value at fault
    TableImage image;
    bool ok() const { return error.isEmpty(); }
};

/// The registers of `table` as version `version` (1…65535) for a controller
/// that takes `capacity` points. Refuses tables it cannot carry exactly:
/// more points than the capacity, positions not equally spaced on the µm
/// grid, values beyond int16 in 0.1 µm.
EncodeResult encodeTable(const compensation::CompensationTable& table, std::uint16_t version,
                         int capacity);

/// The table the registers describe (positions in mm, corrections in µm).
compensation::CompensationTable decodeTable(const TableImage& image);

/// Whether two images hold the same table ("no table", version 0, equals
/// "no table" whatever its other registers hold).
bool sameTable(const TableImage& a, const TableImage& b);
/// The first register of the active table (block 2) where `read` differs
/// from `sent`, as "register 1102 holds 0x…, sent 0x…".
QString firstDifference(const TableImage& sent, const TableImage& read, int capacity);

/// int32 ↔ two registers, high word first.
void putInt32(std::int32_t value, std::uint16_t* high_first);
std::int32_t getInt32(const std::uint16_t* high_first);

}  // namespace driftlab::push
