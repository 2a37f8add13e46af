#pragma once
// Reading the table a controller applies now (block 2 of
// docs/modbus-register-map.md) without pushing anything, and what a new table
// changes against it: the GUI's "Read controller" and the push confirmation.
// The push itself reads the active table with the same function.

#include <QString>
#include <vector>

#include "acquisition/modbus/ModbusLink.h"
#include "acquisition/push/CompensationRegisterMap.h"
#include "core/compensation/CompensationTable.h"

namespace driftlab::push {

/// The active table's registers over an open link; `capacity` is the
/// controller's (register 3). False with `error` when a request fails.
bool readActiveImage(modbus::ModbusLink& link, int capacity, TableImage& image, QString* error);

struct ActiveTable {
    QString error;  ///< empty on success; names the controller and what failed
    QString controller;
    int capacity = 0;
    MachineState state = MachineState::Idle;
    TableImage image;  ///< version 0: the controller holds no table
    bool ok() const { return error.isEmpty(); }
    bool empty() const { return image.version() == 0; }
};

/// Connects, checks that the device serves DriftLab's map, reads the active
/// table and closes. Blocks for at most a few response timeouts: call it off
/// the GUI thread. Writes nothing.
ActiveTable readActiveTable(const modbus::ModbusUrl& url, double response_timeout_s = 1);

/// What `next` changes against the active table, at the points of `next`
/// (the active table interpolated there, see activeAtPointsOf()).
struct TableChange {
    compensation::CompensationTable active;  ///< the active corrections at next's points
    std::vector<double> change_plus_um;      ///< next − active, + column
    std::vector<double> change_minus_um;     ///< next − active, − column
    int points_changed = 0;        ///< points where either column moves by ≥ half a register step
    double largest_change_um = 0;  ///< the largest |change| over both columns
    double largest_at_mm = 0;      ///< where it is
};
TableChange changeAgainst(const TableImage& active, const compensation::CompensationTable& next);

}  // namespace driftlab::push
