#pragma once
// The compensation push over Modbus TCP (docs/modbus-register-map.md, "How a
// push goes"): read the controller's identity and active table, check the new
// table against the limits and the active one, stage it, commit, wait for the
// controller to apply it when the machine is not cutting, read it back, and
// roll back or abort on any mismatch, refusal, timeout or lost connection,
// checking that the previous table is intact.
//
// push() blocks the calling thread for at most about ack_timeout_s plus a few
// response timeouts; run it on a worker thread in the GUI. It reports
// progress and can be cancelled.

#include <QString>
#include <atomic>
#include <functional>

#include "acquisition/modbus/ModbusLink.h"
#include "acquisition/push/CompensationRegisterMap.h"
#include "acquisition/push/PushResult.h"
#include "core/compensation/CompensationTable.h"

namespace driftlab::push {

struct PushOptions {
    /// How long to wait for the controller to apply (the machine may be cutting).
    double ack_timeout_s = 10;
    /// Bounds the connect and every request.
    double response_timeout_s = 1;
    double poll_interval_s = 0.01;
    /// Value and step limits of the table, and the change against the
    /// controller's active table (max_change_um).
    compensation::Limits limits;
    /// Called between steps with the fraction done; returning false cancels.
    std::function<bool(double fraction, const QString& step)> progress;
    /// Set from another thread to cancel.
    const std::atomic_bool* cancel = nullptr;
};

class TablePush {
public:
    TablePush(modbus::ModbusUrl url, PushOptions options);
    PushResult push(const compensation::CompensationTable& table);

private:
    /// A request failed (transport error, timeout or Modbus exception).
    struct LinkError {
        QString error;
    };
    struct Identity {
        int capacity = 0;
        MachineState state = MachineState::Idle;
        std::uint16_t active = 0, previous = 0, ack = 0;
        CommitStatus status = CommitStatus::Nothing;
    };

    // TablePush.cpp: the steps of a push.
    void run(const compensation::CompensationTable& table);
    bool checkTable(const compensation::CompensationTable& table);
    void stage();
    void awaitAck();
    void readBack();
    static Identity identityOf(const std::vector<std::uint16_t>& block0);
    std::vector<std::uint16_t> read(int address, int count);
    void write(int address, std::span<const std::uint16_t> values);
    TableImage readActive();
    void writeCommand(Command command);
    void step(const QString& name, bool ok, const QString& detail);
    void finish(PushOutcome outcome, const QString& message);
    bool cancelled(double fraction, const QString& stepName);

    // TablePushRecovery.cpp: getting the controller back to a known table.
    void recoverAfterLostLink(const QString& error);
    void abortAndVerify(PushOutcome outcome, const QString& why);
    void rollBackAndVerify(const QString& why);
    bool waitForStatus(CommitStatus wanted, double timeout_s);
    bool previousIntact();

    modbus::ModbusLink m_link;
    PushOptions m_options;
    PushResult m_result;
    Identity m_identity;
    TableImage m_before;  ///< the active table read in step 1: what a rollback restores
    TableImage m_sent;
    QString m_stepName;  ///< the step under way, named when the link fails in it
};

/// One push with its own connection (see TablePush).
PushResult pushTable(const modbus::ModbusUrl& url, const compensation::CompensationTable& table,
                     const PushOptions& options = {});

/// `active` evaluated at the points of `next` (linear, end values held beyond
/// its range; zero when there is none): the correction the controller applies
/// there now, for the per-update change limit.
compensation::CompensationTable activeAtPointsOf(const TableImage& active,
                                                 const compensation::CompensationTable& next);

}  // namespace driftlab::push
