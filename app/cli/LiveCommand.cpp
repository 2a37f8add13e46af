// live: live thermal compensation (docs/live-compensation.md) replayed on a measured run.
// The heat-transfer model is fitted on the training runs; the replayed run's
// ambient, torque and motion then drive it online, step by step, and every
// update it applies (only between cuts, limited per update) is printed and,
// with --push, written to the controller's live-offset registers. The
// corrections are scored against the thermal error measured in that run.
#include <QElapsedTimer>
#include <QJsonArray>
#include <QRegularExpression>
#include <QThread>

#include "acquisition/live/LiveOffsetWriter.h"
#include "app/cli/CliCommon.h"
#include "app/cli/FlaggedSamples.h"
#include "app/cli/ThermalProfile.h"
#include "core/compensation/LiveReplay.h"
#include "core/models/HeatTransferModel.h"
#include "core/models/ModelValidation.h"
#include "db/ModelTrustJson.h"

namespace driftlab::cli {
namespace {

using compensation::LiveUpdate;

/// "A-B[,C-D]..." in s: when the replay's machine is cutting.
std::vector<std::pair<double, double>> cuttingWindows(const QString& text) {
    std::vector<std::pair<double, double>> windows;
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
        windows.emplace_back(from, to);
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
        QStringLiteral("Runs the heat-transfer model is fitted on (not the replayed run)."),
        QStringLiteral("R,..")};
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
                   campaignSourceOptions() << runOption << train << interval << position << points
                                           << maxChange << cutting << push << staleAfter << speedup
                                           << keepFlaggedOption() << forceOption(),
                   campaignSourceArguments({runOption, train}));
    const QString runId = parser.value(runOption);
    const QStringList trainRuns = runList(parser.value(train));
    refuseOverlappingRuns(trainRuns, {runId});
    compensation::LiveReplayOptions options;
    options.settings.update_interval_s = positiveNumberOption(parser, interval);
    options.settings.max_change_um = positiveNumberOption(parser, maxChange);
    const int tablePoints = parser.value(points).toInt();
    if (tablePoints < 2 || tablePoints > 1024)
        throw CliError(QStringLiteral("--table-points: '%1' is not a whole number from 2 to 1024")
                           .arg(parser.value(points)),
                       2);

    Campaign campaign = loadCampaignSource(parser);
    leaveOutFlaggedSamples(parser, campaign);
    models::DatasetResult data = models::buildDataset(campaign, trainRuns + QStringList{runId});
    if (!data.ok()) throw CliError(data.error);
    const models::RunData replayed = data.runs.back();
    data.runs.pop_back();
    printProgress(QStringLiteral("fitting heat-transfer"), 0);
    const models::ValidatedFit fitted =
        models::fitValidated(QStringLiteral("heat-transfer"), data.runs);
    printProgress(QStringLiteral("fitting heat-transfer"), 1);
    if (!fitted.fit.success) throw CliError(fitted.fit.message);
    // A rehearsal may show a model that would do harm; a push may not send it.
    const QString what = QStringLiteral("the heat-transfer model fitted on %1")
                             .arg(trainRuns.join(QLatin1Char(',')));
    if (parser.isSet(push))
        refuseHarm(parser, fitted.validation, what);
    else if (fitted.validation.worseThanNone())
        printWarnings({QStringLiteral("%1 does worse than no compensation where it was not "
                                      "fitted (%2): a push would refuse it")
                           .arg(what, fitted.validation.describe())});
    std::vector<models::DataGap> gaps = models::gapsOf(data.runs);
    gaps.insert(gaps.end(), replayed.gaps.begin(), replayed.gaps.end());
    printWarnings(models::gapLines(gaps));
    const auto& model = static_cast<const models::HeatTransferModel&>(*fitted.model);
    QString why;
    const auto screw = model.fittedScrew(replayed, &why);
    if (!screw) throw CliError(why);

    // The table spans the run's measured targets, where its score can be checked.
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& o : replayed.observations) {
        lo = std::min(lo, o.position_mm);
        hi = std::max(hi, o.position_mm);
    }
    if (!(hi > lo)) throw CliError(QStringLiteral("run %1 has no span of targets").arg(runId));
    for (int i = 0; i < tablePoints; ++i)
        options.settings.table_positions_mm.push_back(lo + (hi - lo) * i / (tablePoints - 1));
    options.settings.offset_position_mm =
        parser.isSet(position) ? numberOption(parser, position) : (lo + hi) / 2;

    const models::PredictionInterval& band = fitted.validation.interval;
    const double uncertainty_um =
        band.known() ? band.halfWidthAt(options.settings.offset_position_mm,
                                        models::beyondTraining(data.runs, replayed))
                     : NAN;
    const auto windows = cuttingWindows(parser.value(cutting));
    if (parser.isSet(push) && parser.isSet(cutting))
        throw CliError(QStringLiteral("--cutting goes without --push: the controller says when it "
                                      "cuts"),
                       2);
    bool ok = false;
    const int staleAfter_s = parser.value(staleAfter).toInt(&ok);
    if (!ok || staleAfter_s < 1 || staleAfter_s > 65535)
        throw CliError(QStringLiteral("--live-timeout-s: '%1' is not a whole number of seconds "
                                      "from 1 to 65535")
                           .arg(parser.value(staleAfter)),
                       2);
    const double speedupFactor = parser.isSet(speedup) ? positiveNumberOption(parser, speedup) : 0;
    std::unique_ptr<live::LiveOffsetWriter> controller;
    if (parser.isSet(push)) {
        QString error;
        const auto url = modbus::parseModbusUrl(parser.value(push), &error);
        if (!url) throw CliError(QStringLiteral("--push: ") + error, 2);
        controller = std::make_unique<live::LiveOffsetWriter>(*url, 2.0, staleAfter_s);
        if (!controller->open(&error)) throw CliError(QStringLiteral("--push: ") + error);
    }
    QString controllerError;
    int written = 0;  // updates the controller took
    QElapsedTimer wall;
    wall.start();
    const std::vector<MotionSegment> motion = replayed.motion;
    options.state_at = [&](double t_s) {
        if (speedupFactor > 0) {
            const qint64 due_ms = qint64(t_s * 1000 / speedupFactor);
            if (due_ms > wall.elapsed()) QThread::msleep(quint64(due_ms - wall.elapsed()));
        }
        if (controller && controllerError.isEmpty()) {
            // A controller that stops answering is read as cutting: nothing
            // is applied, and the replay stops at the next update.
            const auto state = controller->machineState(&controllerError);
            return state.value_or(MachineState::Cutting);
        }
        for (const auto& [from, to] : windows)
            if (t_s > from && t_s <= to) return MachineState::Cutting;
        return compensation::stateFromMotion(motion, t_s);
    };
    const bool json = parser.isSet(QStringLiteral("json"));
    options.on_update = [&](const LiveUpdate& u) {
        if (controller) {
            if (!controllerError.isEmpty() ||
                !controller->publish(u.offset_um, true, &controllerError))
                return false;
            ++written;
        }
        if (!json)
            printLine(QStringLiteral("%1 s  offset %2 ± %3 µm at %4 mm%5%6")
                          .arg(u.time_s, 8, 'f', 0)
                          .arg(u.offset_um, 8, 'f', 3)
                          .arg(uncertainty_um, 0, 'f', 2)
                          .arg(options.settings.offset_position_mm, 0, 'f', 1)
                          .arg(u.time_s > u.due_s + 1e-9
                                   ? QStringLiteral("  (due at %1 s, waited for the cut)")
                                         .arg(u.due_s, 0, 'f', 0)
                                   : QString())
                          .arg(u.limited ? QStringLiteral("  (change limited)") : QString()));
        return true;
    };
    const compensation::LiveReplayResult result =
        compensation::replayLive(replayed, *screw, options);
    if (!result.ok()) throw CliError(result.error);
    if (!controllerError.isEmpty())
        throw CliError(QStringLiteral("--push: after %1 updates written: %2")
                           .arg(written)
                           .arg(controllerError));

    const double gain =
        result.rms_before_um > 0 ? 1 - result.rms_after_um / result.rms_before_um : 0;
    if (json) {
        QJsonArray updates;
        for (const LiveUpdate& u : result.updates) updates.append(updateJson(u, uncertainty_um));
        printJson(
            {{QStringLiteral("run"), runId},
             {QStringLiteral("train_runs"), QJsonArray::fromStringList(trainRuns)},
             {QStringLiteral("interval_s"), options.settings.update_interval_s},
             {QStringLiteral("offset_position_mm"), options.settings.offset_position_mm},
             {QStringLiteral("updates"), updates},
             {QStringLiteral("controller"), controller ? controller->url().toString() : QString()},
             {QStringLiteral("readings"), int(result.readings)},
             {QStringLiteral("rms_before_um"), result.rms_before_um},
             {QStringLiteral("rms_after_um"), result.rms_after_um},
             {QStringLiteral("rms_after_offset_um"), result.rms_after_offset_um},
             {QStringLiteral("reduction"), gain},
             {QStringLiteral("validation"), db::validationJson(fitted.validation)},
             {QStringLiteral("gaps"), db::gapsJson(gaps)}});
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
                .arg(options.settings.offset_position_mm, 0, 'f', 1));
    }
    return 0;
}

}  // namespace driftlab::cli
