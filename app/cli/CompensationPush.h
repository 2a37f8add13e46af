#pragma once
// compensate --push: the table over Modbus TCP to a controller
// (acquisition/push/TablePush.h), recorded in the store's push history.

#include <QCommandLineParser>
#include <optional>

#include "acquisition/modbus/ModbusUrl.h"
#include "acquisition/push/PushResult.h"
#include "core/compensation/CompensationTable.h"
#include "core/domain/Campaign.h"

namespace driftlab::cli {

/// --push, --timeout-s, --max-change-um, --history.
QList<QCommandLineOption> pushOptions();

struct PushPlan {
    modbus::ModbusUrl url;
    double timeout_s = 10;
    double max_change_um = 0;  ///< infinity: no limit
    /// Where the push is recorded: the --db store, or --history FILE for a
    /// push from a bundle folder; empty: not recorded.
    QString history_path;
};

/// The push asked for, checked before any work (exit 2 on a bad URL or
/// number; exit 1 when the history store cannot be written); nullopt without --push.
std::optional<PushPlan> planPush(const QCommandLineParser& parser);

/// Pushes `table` (checked against `limits` plus the plan's change limit),
/// records it in the plan's history store and returns what happened.
push::PushResult pushAndRecord(const PushPlan& plan, const QCommandLineParser& parser,
                               const compensation::CompensationTable& table,
                               compensation::Limits limits, const QString& run);
/// Each step and the outcome, on stdout.
void printPush(const PushPlan& plan, const push::PushResult& result);

}  // namespace driftlab::cli
