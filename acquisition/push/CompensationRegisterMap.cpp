#include "acquisition/push/CompensationRegisterMap.h"

#include <cmath>

#include "acquisition/modbus/Crc16Modbus.h"

namespace driftlab::push {
namespace {

/// Positions are carried in whole µm; a point may sit off the grid by at most
/// half the register's resolution, or the controller would correct elsewhere.
constexpr double kGridToleranceUm = 0.5;

QString mm(double value) {
    return QString::number(value, 'f', 4);
}

}  // namespace

QString describe(CommitStatus status) {
    switch (status) {
        case CommitStatus::Nothing:
            return QStringLiteral("nothing pending");
        case CommitStatus::Staged:
            return QStringLiteral("staged, waiting for a safe state");
        case CommitStatus::Applied:
            return QStringLiteral("applied");
        case CommitStatus::Refused:
            return QStringLiteral("refused by the controller");
        case CommitStatus::ChecksumMismatch:
            return QStringLiteral("checksum mismatch");
        case CommitStatus::Aborted:
            return QStringLiteral("aborted");
        case CommitStatus::RolledBack:
            return QStringLiteral("rolled back");
    }
    return QStringLiteral("status %1").arg(int(status));
}

void putInt32(std::int32_t value, std::uint16_t* high_first) {
    const auto bits = std::uint32_t(value);
    high_first[0] = std::uint16_t(bits >> 16);
    high_first[1] = std::uint16_t(bits & 0xFFFF);
}

std::int32_t getInt32(const std::uint16_t* high_first) {
    return std::int32_t((std::uint32_t(high_first[0]) << 16) | high_first[1]);
}

std::int32_t TableImage::start_um() const {
    return getInt32(&header[2]);
}

std::int32_t TableImage::spacing_um() const {
    return getInt32(&header[4]);
}

std::uint16_t TableImage::computeChecksum() const {
    std::vector<std::uint16_t> covered(header.begin(), header.begin() + 7);
    covered.insert(covered.end(), plus.begin(), plus.end());
    covered.insert(covered.end(), minus.begin(), minus.end());
    return modbus::crc16ModbusOfRegisters(covered);
}

EncodeResult encodeTable(const compensation::CompensationTable& table, std::uint16_t version,
                         int capacity) {
    EncodeResult result;
    const std::size_t n = table.size();
    if (version == 0) {
        result.error = QStringLiteral("table version 0 means 'no table'; versions are 1…65535");
        return result;
    }
    if (n < 2 || n > std::size_t(capacity)) {
        result.error = QStringLiteral("%1 points: the controller takes 2 to %2 points per table")
                           .arg(n)
                           .arg(capacity);
        return result;
    }
    const double start_um = std::round(table.position_mm.front() * 1000);
    const double spacing_um = std::round(table.spacing_mm() * 1000);
    if (!(std::abs(start_um) <= INT32_MAX) || !(spacing_um > 0 && spacing_um <= INT32_MAX)) {
        result.error = QStringLiteral("start %1 mm or spacing %2 mm does not fit an int32 of µm")
                           .arg(mm(table.position_mm.front()), mm(table.spacing_mm()));
        return result;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const double grid_um = start_um + double(i) * spacing_um;
        if (!(std::abs(table.position_mm[i] * 1000 - grid_um) <= kGridToleranceUm)) {
            result.error = QStringLiteral(
                               "point %1 at %2 mm is off the equally spaced µm grid (%3 mm "
                               "expected at a spacing of %4 µm)")
                               .arg(i)
                               .arg(mm(table.position_mm[i]), mm(grid_um / 1000))
                               .arg(spacing_um, 0, 'f', 0);
            return result;
        }
    }
    auto column = [&](const std::vector<double>& values, const char* name,
                      std::vector<std::uint16_t>& out) {
        for (std::size_t i = 0; i < n; ++i) {
            const double tenths = std::round(values[i] * 10);
            if (!(tenths >= INT16_MIN && tenths <= INT16_MAX)) {
                result.error = QStringLiteral(
                                   "point %1 at %2 mm: correction%3 %4 µm does not fit the "
                                   "register (int16 in 0.1 µm: -3276.8 to 3276.7 µm)")
                                   .arg(i)
                                   .arg(mm(table.position_mm[i]), QLatin1String(name))
                                   .arg(values[i], 0, 'f', 3);
                return false;
            }
            out.push_back(std::uint16_t(std::int16_t(tenths)));
        }
        return true;
    };
    TableImage& image = result.image;
    const bool bidirectional = table.bidirectional;
    // A unidirectional table carries the mean of both columns (they are equal).
    std::vector<double> plus(n);
    for (std::size_t i = 0; i < n; ++i)
        plus[i] = bidirectional ? table.correction_plus_um[i] : table.meanCorrectionUm(i);
    if (!column(plus, bidirectional ? " +" : "", image.plus)) return result;
    if (bidirectional && !column(table.correction_minus_um, " -", image.minus)) return result;
    image.header[0] = version;
    image.header[1] = std::uint16_t(n);
    putInt32(std::int32_t(start_um), &image.header[2]);
    putInt32(std::int32_t(spacing_um), &image.header[4]);
    image.header[6] = bidirectional ? kFlagBidirectional : 0;
    image.header[7] = image.computeChecksum();
    return result;
}

compensation::CompensationTable decodeTable(const TableImage& image) {
    compensation::CompensationTable table;
    table.bidirectional = image.bidirectional();
    for (int i = 0; i < image.points() && i < int(image.plus.size()); ++i) {
        table.position_mm.push_back((image.start_um() + double(i) * image.spacing_um()) / 1000);
        const double plus = std::int16_t(image.plus[i]) / 10.0;
        table.correction_plus_um.push_back(plus);
        table.correction_minus_um.push_back(table.bidirectional && i < int(image.minus.size())
                                                ? std::int16_t(image.minus[i]) / 10.0
                                                : plus);
    }
    return table;
}

bool sameTable(const TableImage& a, const TableImage& b) {
    return (a.version() == 0 && b.version() == 0) || a == b;
}

QString firstDifference(const TableImage& sent, const TableImage& read, int capacity) {
    const auto differs = [](int address, std::uint16_t was, std::uint16_t is) {
        return QStringLiteral("register %1 holds 0x%2, sent 0x%3")
            .arg(address)
            .arg(is, 4, 16, QLatin1Char('0'))
            .arg(was, 4, 16, QLatin1Char('0'));
    };
    for (int i = 0; i < kHeaderCount; ++i)
        if (sent.header[i] != read.header[i])
            return differs(reg::kActiveHeader + i, sent.header[i], read.header[i]);
    for (bool plus : {true, false}) {
        const auto& was = plus ? sent.plus : sent.minus;
        const auto& is = plus ? read.plus : read.minus;
        const int base = reg::kActiveData + (plus ? 0 : capacity);
        for (std::size_t i = 0; i < std::min(was.size(), is.size()); ++i)
            if (was[i] != is[i]) return differs(base + int(i), was[i], is[i]);
        if (was.size() != is.size())
            return QStringLiteral("%1 registers from %2 read, %3 sent")
                .arg(is.size())
                .arg(base)
                .arg(was.size());
    }
    return QStringLiteral("no difference");
}

}  // namespace driftlab::push
