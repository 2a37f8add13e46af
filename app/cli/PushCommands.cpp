// controller-sim: the simulated controller of DriftLab's Modbus register map,
// served in the foreground until SIGINT/SIGTERM; pushes: the push history of a
// store (docs/compensation.md, "Push to a controller").
#include <QJsonArray>
#include <array>
#include <csignal>
#include <cstdio>

#include "acquisition/sim/SimulatedController.h"
#include "app/cli/CliCommon.h"
#include "db/PushHistory.h"

namespace driftlab::cli {
namespace {

MachineState machineState(const QString& name) {
    const QStringList names{QStringLiteral("idle"), QStringLiteral("moving"),
                            QStringLiteral("cutting"), QStringLiteral("tool-change")};
    const int index = int(names.indexOf(name));
    if (index < 0)
        throw CliError(QStringLiteral("--state: '%1' is not one of %2")
                           .arg(name, names.join(QStringLiteral(", "))),
                       2);
    return MachineState(index);
}

/// --fault F: drop-after-writes=N, refuse-commit, corrupt-after-apply, idle-after-polls=N.
void addFault(sim::ControllerFaults& faults, const QString& fault) {
    const QString name = fault.section(QLatin1Char('='), 0, 0);
    bool ok = true;
    const int n =
        fault.contains(QLatin1Char('=')) ? fault.section(QLatin1Char('='), 1).toInt(&ok) : -1;
    if (name == QLatin1String("refuse-commit") && n == -1)
        faults.refuse_commit = true;
    else if (name == QLatin1String("corrupt-after-apply") && n == -1)
        faults.corrupt_after_apply = true;
    else if (name == QLatin1String("drop-after-writes") && ok && n >= 0)
        faults.drop_after_writes = n;
    else if (name == QLatin1String("idle-after-polls") && ok && n >= 1)
        faults.idle_after_polls = n;
    else
        throw CliError(QStringLiteral("--fault: '%1' is not one of drop-after-writes=N, "
                                      "refuse-commit, corrupt-after-apply, idle-after-polls=N")
                           .arg(fault),
                       2);
}

/// --axis POSITION_MM,FEED_MM_MIN,TORQUE_NM: the axis state served in block 0.
devices::AxisState axisState(const QString& text) {
    const QStringList parts = text.split(QLatin1Char(','));
    std::array<double, 3> values{};
    bool ok = parts.size() == 3;
    for (int i = 0; ok && i < 3; ++i) values[std::size_t(i)] = parts[i].toDouble(&ok);
    if (!ok)
        throw CliError(QStringLiteral("--axis: '%1' is not POSITION_MM,FEED_MM_MIN,TORQUE_NM "
                                      "(three numbers)")
                           .arg(text),
                       2);
    return {values[0], values[1], values[2]};
}

}  // namespace

int controllerSimCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption host{QStringLiteral("host"),
                                  QStringLiteral("IPv4 or IPv6 address, or host name, to listen "
                                                 "on (default 127.0.0.1)."),
                                  QStringLiteral("ADDRESS"), QStringLiteral("127.0.0.1")};
    const QCommandLineOption port{QStringLiteral("port"),
                                  QStringLiteral("TCP port (default 0: a free one, printed)."),
                                  QStringLiteral("N"), QStringLiteral("0")};
    const QCommandLineOption capacity{QStringLiteral("capacity"),
                                      QStringLiteral("Points per table it takes (default 256)."),
                                      QStringLiteral("N"), QStringLiteral("256")};
    const QCommandLineOption state{
        QStringLiteral("state"),
        QStringLiteral("Machine state: idle (default), moving, cutting (tables wait), "
                       "tool-change."),
        QStringLiteral("S"), QStringLiteral("idle")};
    const QCommandLineOption fault{
        QStringLiteral("fault"),
        QStringLiteral("Inject a fault (repeatable): drop-after-writes=N, refuse-commit, "
                       "corrupt-after-apply, idle-after-polls=N (a cut that ends)."),
        QStringLiteral("F")};
    const QCommandLineOption axis{
        QStringLiteral("axis"),
        QStringLiteral("Axis state served in registers 8-13: position mm, feed mm/min, "
                       "torque N·m (default 0,0,0)."),
        QStringLiteral("P,F,T"), QStringLiteral("0,0,0")};
    parseArguments(parser, args, {host, port, capacity, state, fault, axis});
    sim::SimulatedControllerOptions options;
    options.host = parser.value(host);
    if (const auto why = sim::unusableListenHost(options.host))
        throw CliError(QStringLiteral("--host: ") + *why, 2);
    bool ok = false;
    options.port = parser.value(port).toInt(&ok);
    if (!ok || options.port < 0 || options.port > 65535)
        throw CliError(QStringLiteral("--port: '%1' is not 0 to 65535").arg(parser.value(port)), 2);
    options.capacity = parser.value(capacity).toInt(&ok);
    if (!ok) throw CliError(QStringLiteral("--capacity: not a whole number"), 2);
    options.state = machineState(parser.value(state));
    options.axis = axisState(parser.value(axis));
    for (const QString& f : parser.values(fault)) addFault(options.faults, f);

    // Block the stop signals before the server thread starts (it inherits the
    // mask), then wait for one here: a clean, bounded shutdown on Ctrl-C.
    sigset_t stopSignals;
    sigemptyset(&stopSignals);
    sigaddset(&stopSignals, SIGINT);
    sigaddset(&stopSignals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stopSignals, nullptr);
    sim::SimulatedController controller(options);
    QString error;
    if (!controller.start(&error)) throw CliError(error);
    if (parser.isSet(QStringLiteral("json")))
        printJson({{QStringLiteral("url"), controller.url()},
                   {QStringLiteral("port"), controller.port()},
                   {QStringLiteral("capacity"), options.capacity}});
    else
        printLine(QStringLiteral("controller-sim: serving DriftLab's register map on %1 "
                                 "(capacity %2, machine %3); stop with Ctrl-C")
                      .arg(controller.url())
                      .arg(options.capacity)
                      .arg(machineStateName(options.state)));
    std::fflush(stdout);
    int received = 0;
    sigwait(&stopSignals, &received);
    controller.stop();
    std::fprintf(stderr, "controller-sim: stopped (%s), %d table(s) applied\n",
                 received == SIGINT ? "SIGINT" : "SIGTERM", controller.applied());
    return 0;
}

int pushesCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption dbOption{QStringLiteral("db"), QStringLiteral("The DriftLab store."),
                                      QStringLiteral("FILE")};
    const QCommandLineOption campaign{QStringLiteral("campaign"),
                                      QStringLiteral("Only the pushes of this campaign."),
                                      QStringLiteral("ID")};
    parseArguments(parser, args, {dbOption, campaign}, Arguments{{}, {}, {}, {dbOption}});
    std::optional<qint64> campaignId;
    if (parser.isSet(campaign)) {
        bool ok = false;
        campaignId = parser.value(campaign).toLongLong(&ok);
        if (!ok) throw CliError(QStringLiteral("--campaign: not a number"), 2);
    }
    auto store = openSourceStore(parser, db::StoreAccess::ReadOnly);
    QString error;
    const auto pushes = db::pushHistory(*store, campaignId, &error);
    if (!pushes) throw CliError(error);
    if (parser.isSet(QStringLiteral("json"))) {
        QJsonArray list;
        for (const db::PushRecord& p : *pushes)
            list.append(QJsonObject{{QStringLiteral("id"), p.id},
                                    {QStringLiteral("pushed_at"), p.pushed_at},
                                    {QStringLiteral("campaign"),
                                     p.campaign_id ? QJsonValue(*p.campaign_id) : QJsonValue()},
                                    {QStringLiteral("run"), p.run},
                                    {QStringLiteral("controller"), p.controller_url},
                                    {QStringLiteral("version"), p.table_version},
                                    {QStringLiteral("points"), p.points},
                                    {QStringLiteral("checksum"), p.table_checksum},
                                    {QStringLiteral("result"), p.result},
                                    {QStringLiteral("message"), p.message},
                                    {QStringLiteral("table"), p.table},
                                    {QStringLiteral("steps"), p.steps}});
        printJson({{QStringLiteral("pushes"), list}});
        return 0;
    }
    if (pushes->empty()) printLine(QStringLiteral("no pushes recorded in %1").arg(store->path()));
    for (const db::PushRecord& p : *pushes)
        printLine(QStringLiteral("#%1 %2 %3 %4 v%5 %6 points, campaign %7 run %8: %9")
                      .arg(p.id)
                      .arg(p.pushed_at, p.result, p.controller_url)
                      .arg(p.table_version)
                      .arg(p.points)
                      .arg(p.campaign_id ? QString::number(*p.campaign_id) : QStringLiteral("-"),
                           p.run.isEmpty() ? QStringLiteral("-") : p.run, p.message));
    return 0;
}

}  // namespace driftlab::cli
