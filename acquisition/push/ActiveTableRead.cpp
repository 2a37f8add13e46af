#include "acquisition/push/ActiveTableRead.h"

#include <algorithm>
#include <cmath>

#include "acquisition/push/TablePush.h"

namespace driftlab::push {
namespace {

/// The registers carry 0.1 µm: a difference below half of that is rounding.
constexpr double kUnchangedBelow_um = 0.05;

}  // namespace

bool readActiveImage(modbus::ModbusLink& link, int capacity, TableImage& image, QString* error) {
    image = TableImage{};
    std::vector<std::uint16_t> values;
    if (!link.readRegisters(reg::kActiveHeader, kHeaderCount, values, error)) return false;
    std::copy(values.begin(), values.end(), image.header.begin());
    if (image.version() == 0) return true;
    const int points = std::min(image.points(), capacity);
    if (!link.readRegisters(reg::kActiveData, points, image.plus, error)) return false;
    if (image.bidirectional() &&
        !link.readRegisters(reg::kActiveData + capacity, points, image.minus, error))
        return false;
    return true;
}

ActiveTable readActiveTable(const modbus::ModbusUrl& url, double response_timeout_s) {
    ActiveTable result;
    modbus::ModbusLink link(url, response_timeout_s);
    result.controller = url.toString();
    const QString endpoint = url.endpoint();
    QString error;
    std::vector<std::uint16_t> block0;
    if (!link.connect(&error) || !link.readRegisters(0, reg::kIdentityCount, block0, &error)) {
        result.error = error;
        return result;
    }
    if (block0[reg::kMagic] != kMagicValue || block0[reg::kMapVersion] != kMapVersionValue) {
        result.error = QStringLiteral(
                           "%1: registers 0-1 hold 0x%2 version %3, not DriftLab's "
                           "map (0x4446 version 1)")
                           .arg(endpoint)
                           .arg(block0[reg::kMagic], 4, 16, QLatin1Char('0'))
                           .arg(block0[reg::kMapVersion]);
        return result;
    }
    result.capacity = block0[reg::kCapacity];
    result.state = MachineState(block0[reg::kMachineState]);
    if (result.capacity < 2 || result.capacity > kMaxCapacity) {
        result.error = QStringLiteral("%1: capacity %2 (register 3) is not 2 to %3")
                           .arg(endpoint)
                           .arg(result.capacity)
                           .arg(kMaxCapacity);
        return result;
    }
    if (!readActiveImage(link, result.capacity, result.image, &error))
        result.error = QStringLiteral("%1: reading the active table: %2").arg(endpoint, error);
    link.close();
    return result;
}

TableChange changeAgainst(const TableImage& active, const compensation::CompensationTable& next) {
    TableChange change;
    change.active = activeAtPointsOf(active, next);
    for (std::size_t i = 0; i < next.size(); ++i) {
        const double plus = next.correction_plus_um[i] - change.active.correction_plus_um[i];
        const double minus = next.correction_minus_um[i] - change.active.correction_minus_um[i];
        change.change_plus_um.push_back(plus);
        change.change_minus_um.push_back(minus);
        const double largest = std::max(std::abs(plus), std::abs(minus));
        if (largest >= kUnchangedBelow_um) ++change.points_changed;
        if (largest > change.largest_change_um) {
            change.largest_change_um = largest;
            change.largest_at_mm = next.position_mm[i];
        }
    }
    return change;
}

}  // namespace driftlab::push
