#include "app/cli/CompensationPush.h"

#include <QJsonArray>
#include <limits>

#include "acquisition/push/PushRecording.h"
#include "acquisition/push/TablePush.h"
#include "app/cli/CliCommon.h"

namespace driftlab::cli {
namespace {

const QCommandLineOption kPush{
    QStringLiteral("push"),
    QStringLiteral("Push the table to a controller over Modbus TCP (docs/modbus-register-map.md): "
                   "staged, checksummed, applied when the machine is not cutting, read back, "
                   "rolled back on any mismatch."),
    QStringLiteral("modbus://HOST:PORT[/UNIT]")};
const QCommandLineOption kTimeout{
    QStringLiteral("timeout-s"),
    QStringLiteral("How long the push waits for the controller to apply the table (default 10)."),
    QStringLiteral("S"), QStringLiteral("10")};
const QCommandLineOption kMaxChange{
    QStringLiteral("max-change-um"),
    QStringLiteral("Largest change against the controller's active table at any point (default: "
                   "no limit)."),
    QStringLiteral("C")};
const QCommandLineOption kHistory{
    QStringLiteral("history"),
    QStringLiteral("Store whose push history records a push from a bundle folder (a push from "
                   "--db is recorded in that store)."),
    QStringLiteral("FILE")};

void record(const PushPlan& plan, const QCommandLineParser& parser,
            const compensation::CompensationTable& table, const QString& run,
            const push::PushResult& result) {
    if (plan.history_path.isEmpty()) return;
    std::optional<qint64> campaignId;
    if (parser.isSet(QStringLiteral("db")))
        campaignId = parser.value(QStringLiteral("campaign")).toLongLong();
    const db::PushRecord push = push::pushRecord(table, campaignId, run, result);
    QString error;
    if (!push::recordPush(plan.history_path, push, &error))
        throw CliError(QStringLiteral("push %1 (%2), but not recorded: %3")
                           .arg(push.result, result.message, error));
}

}  // namespace

QList<QCommandLineOption> pushOptions() {
    return {kPush, kTimeout, kMaxChange, kHistory};
}

std::optional<PushPlan> planPush(const QCommandLineParser& parser) {
    if (!parser.isSet(kPush)) {
        for (const auto& option : {kTimeout, kMaxChange, kHistory})
            if (parser.isSet(option))
                throw CliError(QStringLiteral("--%1 goes with --push").arg(option.names().front()),
                               2);
        return std::nullopt;
    }
    PushPlan plan;
    QString error;
    const auto url = modbus::parseModbusUrl(parser.value(kPush), &error);
    if (!url) throw CliError(QStringLiteral("--push: ") + error, 2);
    plan.url = *url;
    plan.timeout_s = positiveNumberOption(parser, kTimeout);
    plan.max_change_um = parser.isSet(kMaxChange) ? positiveNumberOption(parser, kMaxChange)
                                                  : std::numeric_limits<double>::infinity();
    const bool fromStore = parser.isSet(QStringLiteral("db"));
    if (fromStore && parser.isSet(kHistory))
        throw CliError(QStringLiteral("--history is for a push from a bundle folder; a push from "
                                      "--db is recorded in that store"),
                       2);
    plan.history_path = fromStore ? parser.value(QStringLiteral("db")) : parser.value(kHistory);
    // A store that cannot take the record is refused before the push, not after.
    if (!plan.history_path.isEmpty() &&
        !db::CampaignStore::open(plan.history_path, db::StoreAccess::ReadWrite, &error))
        throw CliError(error);
    return plan;
}

push::PushResult pushAndRecord(const PushPlan& plan, const QCommandLineParser& parser,
                               const compensation::CompensationTable& table,
                               compensation::Limits limits, const QString& run) {
    push::PushOptions options;
    options.ack_timeout_s = plan.timeout_s;
    limits.max_change_um = plan.max_change_um;
    options.limits = limits;
    options.progress = [](double fraction, const QString& step) {
        return printProgress(QStringLiteral("push (%1)").arg(step), fraction);
    };
    const push::PushResult result = push::pushTable(plan.url, table, options);
    endProgressLine();
    record(plan, parser, table, run, result);
    return result;
}

void printPush(const PushPlan& plan, const push::PushResult& result) {
    printLine(
        QStringLiteral("push to %1: %2").arg(result.controller, push::outcomeName(result.outcome)));
    for (const push::PushStep& step : result.steps)
        printLine(QStringLiteral("  %1 %2 %3")
                      .arg(step.name, -16)
                      .arg(step.ok ? QStringLiteral("ok  ") : QStringLiteral("FAIL"))
                      .arg(step.detail));
    if (!plan.history_path.isEmpty())
        printLine(QStringLiteral("recorded in the push history of %1").arg(plan.history_path));
}

}  // namespace driftlab::cli
