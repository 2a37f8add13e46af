#pragma once
// What a compensation push did, step by step: for the CLI, the GUI and the
// store's push history.

#include <QJsonObject>
#include <QString>
#include <cstdint>
#include <optional>
#include <vector>

namespace driftlab::push {

/// The push history's result column: applied, rolled_back, refused, failed.
enum class PushOutcome {
    Applied,     ///< active on the controller and read back equal
    RolledBack,  ///< applied, read back different, the previous table restored
    Refused,     ///< refused before any write (limits, capacity) or by the controller
    Failed,      ///< not applied: unreachable, timeout, checksum, lost connection, cancelled
};

QString outcomeName(PushOutcome outcome);

struct PushStep {
    QString name;  ///< connect, identify, read_active, check, abort_leftover, stage, …
    bool ok = false;
    QString detail;
};

struct PushResult {
    PushOutcome outcome = PushOutcome::Failed;
    QString message;  ///< one line: what happened and what the controller holds now
    std::vector<PushStep> steps;
    QString controller;               ///< modbus://host:port
    std::uint16_t version = 0;        ///< the pushed table's version (0: none chosen)
    std::uint16_t active_before = 0;  ///< the version active before the push
    int points = 0;
    std::uint16_t checksum = 0;  ///< CRC-16/MODBUS of the pushed registers
    int capacity = 0;            ///< the controller's, 0 when not read
    /// After a failure: whether the table active before the push was read back
    /// intact (nullopt: not checked, e.g. nothing was written or no connection).
    std::optional<bool> previous_intact;
    int write_requests = 0;  ///< Modbus write requests sent (0: nothing written)
    int requests = 0;        ///< all requests, reads included
    double elapsed_s = 0;

    bool ok() const { return outcome == PushOutcome::Applied; }
    QJsonObject toJson() const;
};

}  // namespace driftlab::push
