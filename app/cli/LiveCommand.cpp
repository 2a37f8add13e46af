// live: live thermal compensation (docs/live-compensation.md) replayed on a measured run.
// The heat-transfer model, or an adopted extension of it (--model), is
// fitted on the training runs; the replayed run's
// ambient, torque and motion then drive it online, step by step, and every
// update it applies (only between cuts, limited per update) is printed and,
// with --push, written to the controller's live-offset registers. The
// corrections are scored against the thermal error measured in that run.
// The work is acquisition/live/LiveCompensationService's, shared with the GUI;
// this file parses, prints and maps errors to exit codes.
#include <QJsonArray>
#include <QRegularExpression>

#include "acquisition/live/LiveCompensationService.h"
#include "app/cli/CliCommon.h"
#include "app/cli/FlaggedSamples.h"
#include "app/cli/ThermalProfile.h"
#include "db/ModelTrustJson.h"

namespace driftlab::cli {
namespace {

using compensation::LiveUpdate;

/// "A-B[,C-D]..." in s: when the replay's machine is cutting.
std::vector<live::CuttingWindow> cuttingWindows(const QString& text) {
    std::vector<live::CuttingWindow> windows;
    static const QRegularExpression window(
        QStringLiteral("^\\s*([0-9.eE+]+)\\s*-\\s*([0-9.eE+]+)\\s*$"));
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const auto m = window.match(part);
        bool okFrom = false, okTo = false;
        const double from = m.hasMatch() ? m.captured(1).toDouble(&okFrom) : 0;
        const double to = m.hasMatch() ? m.captured(2).toDouble(&okTo) : 0;
        if (!okFrom || !okTo || !(to > from))
            throw CliError(
                QStringLiteral("--cutting: '%1' is not a time window FROM-TO in s").arg(part), 2);
        windows.push_back({from, to});
    }
    return windows;
}

QJsonObject updateJson(const LiveUpdate& u, double uncertainty_um) {
    return {{QStringLiteral("time_s"), u.time_s},
            {QStringLiteral("due_s"), u.due_s},
            {QStringLiteral("offset_um"), u.offset_um},
            {QStringLiteral("uncertainty_um"), jsonNumber(uncertainty_um)},
            {QStringLiteral("limited"), u.limited}};
}

}  // namespace

int liveCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption runOption{QStringLiteral("run"),
                                       QStringLiteral("The run replayed as live data."),
                                       QStringLiteral("R")};
    const QCommandLineOption train{
        QStringLiteral("train"),
        QStringLiteral("Runs the model is fitted on (not the replayed run)."),
        QStringLiteral("R,..")};
    const QCommandLineOption model{
        QStringLiteral("model"),
        QStringLiteral("heat-transfer (default), or an extension a diagnosis adopted, "
                       "heat-transfer+CAUSE, for causes on the screw's heat flow (motor_heat, "
                       "forced_convection, nut_heat_exponent)."),
        QStringLiteral("NAME"), QStringLiteral("heat-transfer")};
    const QCommandLineOption interval{QStringLiteral("interval-s"),
                                      QStringLiteral("Update interval (default 60)."),
                                      QStringLiteral("S"), QStringLiteral("60")};
    const QCommandLineOption position{
        QStringLiteral("position"),
        QStringLiteral("Working position of the live offset (default: the middle of the run's "
                       "measured targets)."),
        QStringLiteral("MM")};
    const QCommandLineOption points{QStringLiteral("table-points"),
                                    QStringLiteral("Points of the live table (default 128)."),
                                    QStringLiteral("N"), QStringLiteral("128")};
    const QCommandLineOption maxChange{
        QStringLiteral("max-change-um"),
        QStringLiteral("Largest change of any value per update (default 5)."), QStringLiteral("C"),
        QStringLiteral("5")};
    const QCommandLineOption cutting{
        QStringLiteral("cutting"),
        QStringLiteral("Time windows of the run in which the machine is cutting, FROM-TO s, "
                       "comma-separated (default: none; with --push the controller says)."),
        QStringLiteral("WINDOWS")};
    const QCommandLineOption push{
        QStringLiteral("push"),
        QStringLiteral("Write each update to the controller's live-offset registers (block 3 of "
                       "docs/modbus-register-map.md) and take the machine state from it."),
        QStringLiteral("modbus://HOST:PORT")};
    const QCommandLineOption staleAfter{
        QStringLiteral("live-timeout-s"),
        QStringLiteral("With --push: the controller flags the offset stale after this long "
                       "without an update (default 600)."),
        QStringLiteral("S"), QStringLiteral("600")};
    const QCommandLineOption speedup{
        QStringLiteral("speedup"),
        QStringLiteral("Replay N times faster than the run was logged (default: as fast as "
                       "possible)."),
        QStringLiteral("N")};
    parseArguments(parser, args,
                   campaignSourceOptions() << runOption << train << model << interval << position
                                           << points << maxChange << cutting << push << staleAfter
                                           << speedup << keepFlaggedOption() << forceOption(),
                   campaignSourceArguments({runOption, train}));
    live::LiveCompensationOptions options;
    options.run = parser.value(runOption);
    options.train_runs = runList(parser.value(train));
    options.model = parser.value(model);
    const QString& runId = options.run;
    const QStringList& trainRuns = options.train_runs;
    refuseOverlappingRuns(trainRuns, {runId});
    options.update_interval_s = positiveNumberOption(parser, interval);
    options.max_change_um = positiveNumberOption(parser, maxChange);
    options.table_points = parser.value(points).toInt();
    if (options.table_points < 2 || options.table_points > 1024)
        throw CliError(QStringLiteral("--table-points: '%1' is not a whole number from 2 to 1024")
                           .arg(parser.value(points)),
                       2);
    if (parser.isSet(position)) options.offset_position_mm = numberOption(parser, position);
    options.cutting = cuttingWindows(parser.value(cutting));
    if (parser.isSet(push) && parser.isSet(cutting))
        throw CliError(QStringLiteral("--cutting goes without --push: the controller says when it "
                                      "cuts"),
                       2);
    bool ok = false;
    options.stale_after_s = parser.value(staleAfter).toInt(&ok);
    if (!ok || options.stale_after_s < 1 || options.stale_after_s > 65535)
        throw CliError(QStringLiteral("--live-timeout-s: '%1' is not a whole number of seconds "
                                      "from 1 to 65535")
                           .arg(parser.value(staleAfter)),
                       2);
    if (parser.isSet(speedup)) options.speedup = positiveNumberOption(parser, speedup);
    if (parser.isSet(push)) {
        QString error;
        options.controller = modbus::parseModbusUrl(parser.value(push), &error);
        if (!options.controller) throw CliError(QStringLiteral("--push: ") + error, 2);
    }
    options.override_no_harm = parser.isSet(forceOption());
    options.progress = printProgress;

    Campaign campaign = loadCampaignSource(parser);
    leaveOutFlaggedSamples(parser, campaign);
    const live::LivePlan plan = live::planLive(campaign, options);
    // A rehearsal may show a model that would do harm; a push may not send it.
    if (parser.isSet(push))
        refuseHarm(parser, plan.validation, plan.model());
    else if (plan.validation.worseThanNone())
        printWarnings({QStringLiteral("%1 does worse than no compensation where it was not "
                                      "fitted (%2): a push would refuse it")
                           .arg(plan.model(), plan.validation.describe())});
    printWarnings(models::gapLines(plan.gaps));

    const bool json = parser.isSet(QStringLiteral("json"));
    const double offsetPosition_mm = plan.settings.offset_position_mm;
    const double uncertainty_um = plan.uncertainty_um;
    if (!json)
        options.on_update = [&](const LiveUpdate& u) {
            printLine(QStringLiteral("%1 s  offset %2 ± %3 µm at %4 mm%5%6")
                          .arg(u.time_s, 8, 'f', 0)
                          .arg(u.offset_um, 8, 'f', 3)
                          .arg(uncertainty_um, 0, 'f', 2)
                          .arg(offsetPosition_mm, 0, 'f', 1)
                          .arg(u.time_s > u.due_s + 1e-9
                                   ? QStringLiteral("  (due at %1 s, waited for the cut)")
                                         .arg(u.due_s, 0, 'f', 0)
                                   : QString())
                          .arg(u.limited ? QStringLiteral("  (change limited)") : QString()));
        };
    live::LiveRunResult run;
    try {
        run = live::runLive(plan, options);
    } catch (const live::ControllerError& e) {
        throw CliError(QStringLiteral("--push: ") + e.message());
    }
    if (!run.controller_error.isEmpty())
        throw CliError(QStringLiteral("--push: after %1 updates written: %2")
                           .arg(run.written)
                           .arg(run.controller_error));
    const compensation::LiveReplayResult& result = run.replay;

    const double gain = run.reduction();
    if (json) {
        QJsonArray updates;
        for (const LiveUpdate& u : result.updates) updates.append(updateJson(u, uncertainty_um));
        printJson({{QStringLiteral("run"), runId},
                   {QStringLiteral("train_runs"), QJsonArray::fromStringList(trainRuns)},
                   {QStringLiteral("model"), plan.model_name},
                   {QStringLiteral("interval_s"), plan.settings.update_interval_s},
                   {QStringLiteral("offset_position_mm"), offsetPosition_mm},
                   {QStringLiteral("updates"), updates},
                   {QStringLiteral("controller"), run.controller},
                   {QStringLiteral("readings"), int(result.readings)},
                   {QStringLiteral("rms_before_um"), result.rms_before_um},
                   {QStringLiteral("rms_after_um"), result.rms_after_um},
                   {QStringLiteral("rms_after_offset_um"), result.rms_after_offset_um},
                   {QStringLiteral("reduction"), gain},
                   {QStringLiteral("validation"), db::validationJson(plan.validation)},
                   {QStringLiteral("gaps"), db::gapsJson(plan.gaps)}});
    } else {
        printLine(
            QStringLiteral("%1 updates; on %2's %3 readings the thermal error goes from %4 to "
                           "%5 µm RMS with the live table (%6 %), to %7 µm RMS with the "
                           "single offset at %8 mm applied everywhere")
                .arg(result.updates.size())
                .arg(runId)
                .arg(result.readings)
                .arg(result.rms_before_um, 0, 'f', 2)
                .arg(result.rms_after_um, 0, 'f', 2)
                .arg(100 * gain, 0, 'f', 0)
                .arg(result.rms_after_offset_um, 0, 'f', 2)
                .arg(offsetPosition_mm, 0, 'f', 1));
    }
    return 0;
}

}  // namespace driftlab::cli
