// compensate: a pitch-error compensation table from a run's positioning
// readings (the cold geometric error, ISO 230-2 mean deviations), written for
// a controller (docs/compensation.md, docs/cli.md).
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "app/cli/CliCommon.h"
#include "app/cli/CommandTable.h"
#include "app/cli/CompensationPush.h"
#include "app/cli/FlaggedSamples.h"
#include "app/cli/ThermalProfile.h"
#include "core/compensation/ActiveTableRead.h"
#include "core/compensation/FormatOptions.h"
#include "core/compensation/Recompensation.h"
#include "core/compensation/TableExport.h"
#include "db/ModelTrustJson.h"

namespace driftlab::cli {
namespace {

using namespace driftlab::compensation;

/// The table formats, then the straight-line temperature formats (ThermalProfile.h).
const QStringList kFormats = tableFormats()
                             << QStringLiteral("sinumerik-temp") << QStringLiteral("isg-temp");

QJsonArray uncertaintyJson(const CompensationTable& table) {
    QJsonArray values;
    for (double u : table.uncertainty_um) values.append(jsonNumber(u));
    return values;
}

QString umWithUnit(double value) {
    return std::isfinite(value) ? QString::number(value, 'f', 3) + QStringLiteral(" µm")
                                : QStringLiteral("n/a");
}

/// The change of every point against the active table, in the sign the
/// file holds (`sign`).
QJsonArray changesJson(const RecompensationResult& r, ValueSign sign) {
    QJsonArray points;
    for (const PointChange& c : r.changes) {
        QJsonObject point{{QStringLiteral("position_mm"), c.position_mm},
                          {QStringLiteral("old_um"), signedValue(c.old_plus_um, sign)},
                          {QStringLiteral("new_um"), signedValue(c.new_plus_um, sign)},
                          {QStringLiteral("change_um"), signedValue(c.changePlusUm(), sign)}};
        if (r.table.bidirectional) {
            point[QStringLiteral("old_minus_um")] = signedValue(c.old_minus_um, sign);
            point[QStringLiteral("new_minus_um")] = signedValue(c.new_minus_um, sign);
            point[QStringLiteral("change_minus_um")] = signedValue(c.changeMinusUm(), sign);
        }
        points.append(point);
    }
    return points;
}

double largestChangeUm(const RecompensationResult& r) {
    double largest = 0;
    for (const PointChange& c : r.changes)
        largest = std::max({largest, std::abs(c.changePlusUm()), std::abs(c.changeMinusUm())});
    return largest;
}

QByteArray readActiveTableFile(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw CliError(
            QStringLiteral("--active-table: cannot read %1: %2").arg(path, file.errorString()));
    return file.readAll();
}

}  // namespace

int compensateCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption format{
        QStringLiteral("format"),
        QStringLiteral("Controller format: %1.").arg(kFormats.join(QStringLiteral(", "))),
        QStringLiteral("F")};
    const QCommandLineOption out{QStringLiteral("out"),
                                 QStringLiteral("File to write (replaced atomically)."),
                                 QStringLiteral("FILE")};
    const QCommandLineOption runOption{
        QStringLiteral("run"),
        QStringLiteral("The run whose positioning readings give the error (default: the "
                       "positioning run, or the only run with positioning readings)."),
        QStringLiteral("R")};
    const QCommandLineOption spacing{QStringLiteral("spacing"),
                                     QStringLiteral("Distance between table points."),
                                     QStringLiteral("MM")};
    const QCommandLineOption points{
        QStringLiteral("points"),
        QStringLiteral("Number of table points (default: one per measured target)."),
        QStringLiteral("N")};
    const QCommandLineOption start{
        QStringLiteral("start"),
        QStringLiteral("First point (default: the first measured target; never below it)."),
        QStringLiteral("MM")};
    const QCommandLineOption end{
        QStringLiteral("end"),
        QStringLiteral("Last point (default: the last measured target; never beyond it)."),
        QStringLiteral("MM")};
    const QCommandLineOption bidirectional{
        QStringLiteral("bidirectional"),
        QStringLiteral("Separate corrections for the + and - approach instead of their mean "
                       "plus a backlash value.")};
    const QCommandLineOption maxValue{QStringLiteral("max-value-um"),
                                      QStringLiteral("Largest |correction| allowed (default 100)."),
                                      QStringLiteral("V"), QStringLiteral("100")};
    const QCommandLineOption maxStep{
        QStringLiteral("max-step-um"),
        QStringLiteral("Largest correction step between neighbouring points (default 20)."),
        QStringLiteral("S"), QStringLiteral("20")};
    const QCommandLineOption axis{
        QStringLiteral("axis"),
        QStringLiteral("Sinumerik machine axis name (default AX1), Heidenhain axis key (default: "
                       "the campaign's axis) or Fanuc axis number (default 1)."),
        QStringLiteral("X")};
    const QCommandLineOption magnification{
        QStringLiteral("magnification"),
        QStringLiteral("Fanuc pitch error compensation magnification, parameter 3623 (default 1)."),
        QStringLiteral("N"), QStringLiteral("1")};
    const QCommandLineOption sign{
        QStringLiteral("sign"),
        QStringLiteral("Values as the correction (added to the command, = -error) or the error "
                       "(actual - target); default: the format's own convention."),
        QStringLiteral("correction|error")};
    const QCommandLineOption values{
        QStringLiteral("values"),
        QStringLiteral("Absolute values, or incremental (the change from the previous point); "
                       "default: the format's own."),
        QStringLiteral("absolute|incremental")};
    const QCommandLineOption activeTable{
        QStringLiteral("active-table"),
        QStringLiteral("The table that was active during the measurement (the format's own file "
                       "or DriftLab CSV): the run's residual is added to it."),
        QStringLiteral("FILE")};
    parseArguments(parser, args,
                   campaignSourceOptions()
                       << format << out << runOption << spacing << points << start << end
                       << bidirectional << maxValue << maxStep << axis << magnification << sign
                       << values << activeTable << thermalProfileOptions() << keepFlaggedOption()
                       << pushOptions(),
                   campaignSourceArguments());

    // A file, a push, or both; the push options are checked before any work.
    const std::optional<PushPlan> plan = planPush(parser);
    const bool writeFile = parser.isSet(format) || parser.isSet(out);
    if (!plan && !writeFile)
        throw CliError(QStringLiteral("give --format F --out FILE, --push modbus://HOST:PORT, or "
                                      "both"),
                       2);
    if (writeFile && !(parser.isSet(format) && parser.isSet(out)))
        throw CliError(QStringLiteral("--format and --out go together"), 2);
    const QString formatName = parser.value(format);
    if (writeFile && !kFormats.contains(formatName))
        throw CliError(QStringLiteral("--format: '%1' is not one of %2")
                           .arg(formatName, kFormats.join(QStringLiteral(", "))),
                       2);
    TableSettings settings;
    if (parser.isSet(spacing) && parser.isSet(points))
        throw CliError(QStringLiteral("give --spacing or --points, not both"), 2);
    if (parser.isSet(spacing)) settings.spacing_mm = positiveNumberOption(parser, spacing);
    if (parser.isSet(points)) {
        bool ok = false;
        settings.points = parser.value(points).toInt(&ok);
        if (!ok || settings.points < 2)
            throw CliError(QStringLiteral("--points: '%1' is not a whole number of at least 2")
                               .arg(parser.value(points)),
                           2);
    }
    if (parser.isSet(start)) settings.start_mm = numberOption(parser, start);
    if (parser.isSet(end)) settings.end_mm = numberOption(parser, end);
    settings.bidirectional = parser.isSet(bidirectional);
    if (parser.isSet(sign)) {
        settings.sign = parseSign(parser.value(sign));
        if (!settings.sign)
            throw CliError(
                QStringLiteral("--sign: '%1' is not correction or error").arg(parser.value(sign)),
                2);
    }
    if (parser.isSet(values)) {
        settings.values = parseMode(parser.value(values));
        if (!settings.values)
            throw CliError(QStringLiteral("--values: '%1' is not absolute or incremental")
                               .arg(parser.value(values)),
                           2);
    }
    // A push carries corrections in the register map's own layout.
    if ((settings.sign || settings.values) && (!writeFile || isTemperatureLineFormat(formatName)))
        throw CliError(QStringLiteral("--sign and --values say how a table file holds its values: "
                                      "give --format F (a table format) and --out FILE"),
                       2);
    if (writeFile && !isTemperatureLineFormat(formatName)) {
        const QString why =
            checkFormatOptions(formatName, settings.sign, settings.values, settings.bidirectional);
        if (!why.isEmpty()) throw CliError(why, 2);
    }
    if (parser.isSet(activeTable) && writeFile && isTemperatureLineFormat(formatName))
        throw CliError(QStringLiteral("--active-table updates a table, not the line of --format %1")
                           .arg(formatName),
                       2);
    Limits limits;
    limits.max_value_um = positiveNumberOption(parser, maxValue);
    limits.max_step_um = positiveNumberOption(parser, maxStep);
    bool ok = false;
    TableExportSettings exportSettings;
    exportSettings.axis = parser.value(axis);
    exportSettings.magnification = parser.value(magnification).toInt(&ok);
    if (!ok || exportSettings.magnification < 1)
        throw CliError(QStringLiteral("--magnification: '%1' is not a whole number of at least 1")
                           .arg(parser.value(magnification)),
                       2);
    if (writeFile && !isTemperatureLineFormat(formatName)) {
        const QString why = checkTableExport(formatName, exportSettings);
        if (!why.isEmpty()) throw CliError(QStringLiteral("--") + why, 2);
    }

    // The active table is read first: a file that cannot be used stops the
    // command before the campaign is loaded.
    ActiveTableRead active;
    if (parser.isSet(activeTable)) {
        const QString path = parser.value(activeTable);
        active = readActiveTable(readActiveTableFile(path), writeFile ? formatName : QString(),
                                 settings.sign, path);
        if (!active.ok()) throw CliError(QStringLiteral("--active-table: ") + active.error);
    }

    // A push is recorded in the --db store: open it for writing from the start.
    Campaign campaign =
        loadCampaignSource(parser, plan ? db::StoreAccess::ReadWrite : db::StoreAccess::ReadOnly);
    // Only the model of the thermal profile reads sensor samples.
    if (wantsThermalProfile(parser)) leaveOutFlaggedSamples(parser, campaign);
    if (campaign.screw) settings.screw_lead_mm = std::max(campaign.screw->lead_mm, 0.0);
    const Run& run = choosePositioningRun(campaign, parser.value(runOption));
    QString source = QStringLiteral("run %1 of %2").arg(run.id, campaign.name);
    const iso::Evaluation evaluation = iso::evaluate(iso::readingsOf(run));
    if (!evaluation.ok()) throw CliError(source + QStringLiteral(": ") + evaluation.error);
    const bool lineFormat = writeFile && isTemperatureLineFormat(formatName);
    if (lineFormat && plan)
        throw CliError(
            QStringLiteral("--push carries a table, not the line of --format %1").arg(formatName),
            2);
    if (lineFormat && !wantsThermalProfile(parser))
        throw CliError(QStringLiteral("--format %1 is a line through a model's thermal error: "
                                      "give --model and --at RUN@SECONDS")
                           .arg(formatName),
                       2);
    std::optional<ThermalProfile> thermal;
    if (wantsThermalProfile(parser)) {
        thermal = thermalProfile(parser, campaign, evaluation.targets.front().target_mm,
                                 evaluation.targets.back().target_mm);
        source += QStringLiteral(" + thermal error of ") + thermal->description;
    }
    if (lineFormat) return writeTemperatureLine(parser, *thermal, formatName, source);
    // With an active table the run measured the residual: the limits apply
    // to the sum, not to the residual alone.
    const double none = std::numeric_limits<double>::infinity();
    const TableResult built = buildTable(
        evaluation, settings, parser.isSet(activeTable) ? Limits{none, none, none} : limits,
        thermal ? thermal->error_um : ErrorProfile{},
        thermal ? thermal->uncertainty_um : ErrorProfile{});
    if (!built.ok()) throw CliError(source + QStringLiteral(": ") + built.error);
    QStringList warnings = evaluation.warnings + built.warnings;
    std::optional<RecompensationResult> recompensated;
    if (parser.isSet(activeTable)) {
        const QString path = parser.value(activeTable);
        recompensated = recompensate(active.table, built.table, limits, settings.max_points);
        if (!recompensated->ok())
            throw CliError(QStringLiteral("active table %1 + residual of %2: %3")
                               .arg(QFileInfo(path).fileName(), source, recompensated->error));
        source = QStringLiteral("active table %1 + residual of %2")
                     .arg(QFileInfo(path).fileName(), source);
        warnings += recompensated->warnings;
    }
    const CompensationTable& table = recompensated ? recompensated->table : built.table;
    // The sign the file holds (a push carries corrections).
    const ValueSign writtenSign =
        writeFile ? effectiveSign(formatName, settings.sign) : ValueSign::Correction;
    const ValueMode writtenMode =
        writeFile ? effectiveMode(formatName, settings.values) : ValueMode::Absolute;
    if (writeFile) {
        exportSettings.campaign_axis = campaign.machine.axis;
        const ExportResult exported = exportTable(table, formatName, exportSettings);
        if (!exported.ok()) throw CliError(formatName + QStringLiteral(": ") + exported.error);
        writeFileAtomically(parser.value(out), exported.text);
        warnings += exported.warnings;
    }
    printWarnings(warnings);
    const bool json = parser.isSet(QStringLiteral("json"));
    std::optional<push::PushResult> pushed;
    if (plan) pushed = pushAndRecord(*plan, parser, table, limits, run.id);
    // The summary first, then the push's failure as the last stderr line.
    const auto failIfNotApplied = [&] {
        if (pushed && !pushed->ok())
            throw CliError(QStringLiteral("push %1: %2")
                               .arg(push::outcomeName(pushed->outcome), pushed->message));
    };

    const double maxUncertainty =
        table.uncertainty_um.empty()
            ? NAN
            : *std::max_element(table.uncertainty_um.begin(), table.uncertainty_um.end());
    if (json) {
        printJson(
            {{QStringLiteral("source"), source},
             {QStringLiteral("run"), run.id},
             {QStringLiteral("format"), writeFile ? QJsonValue(formatName) : QJsonValue()},
             {QStringLiteral("out"), writeFile ? QJsonValue(parser.value(out)) : QJsonValue()},
             {QStringLiteral("push"), pushed ? QJsonValue(pushed->toJson()) : QJsonValue()},
             {QStringLiteral("points"), int(table.size())},
             {QStringLiteral("start_mm"), table.position_mm.front()},
             {QStringLiteral("end_mm"), table.position_mm.back()},
             {QStringLiteral("spacing_mm"), table.spacing_mm()},
             {QStringLiteral("bidirectional"), table.bidirectional},
             {QStringLiteral("max_correction_um"), table.maxAbsCorrectionUm()},
             {QStringLiteral("B_mean_um"), jsonNumber(table.mean_reversal_um)},
             {QStringLiteral("cycles"), evaluation.cycles},
             {QStringLiteral("thermal"), thermal ? QJsonValue(thermal->description) : QJsonValue()},
             {QStringLiteral("validation"),
              thermal ? QJsonValue(db::validationJson(thermal->validation)) : QJsonValue()},
             {QStringLiteral("uncertainty_um"), uncertaintyJson(table)},
             {QStringLiteral("max_uncertainty_um"), jsonNumber(maxUncertainty)},
             {QStringLiteral("value_sign"), signName(writtenSign)},
             {QStringLiteral("values"), modeName(writtenMode)},
             {QStringLiteral("active_table"),
              recompensated
                  ? QJsonValue(QJsonObject{
                        {QStringLiteral("file"), parser.value(activeTable)},
                        {QStringLiteral("layout"), active.layout},
                        {QStringLiteral("points"), int(active.table.size())},
                        {QStringLiteral("max_change_um"), largestChangeUm(*recompensated)},
                        {QStringLiteral("changes"), changesJson(*recompensated, writtenSign)}})
                  : QJsonValue()},
             {QStringLiteral("sign"),
              writtenSign == ValueSign::Correction
                  ? QStringLiteral("correction = -(actual - target), added to the command")
                  : QStringLiteral("error = actual - target, which the controller subtracts")}});
        failIfNotApplied();
        return 0;
    }
    printLine(QStringLiteral("%1 table from %2 (ISO 230-2 mean deviations over %3 cycles) → %4")
                  .arg(writeFile ? formatName : QStringLiteral("compensation"), source)
                  .arg(evaluation.cycles)
                  .arg(writeFile ? QFileInfo(parser.value(out)).fileName() : plan->url.toString()));
    printLine(QStringLiteral("points: %1, %2 to %3 mm every %4 mm, %5")
                  .arg(table.size())
                  .arg(table.position_mm.front(), 0, 'f', 3)
                  .arg(table.position_mm.back(), 0, 'f', 3)
                  .arg(table.spacing_mm(), 0, 'f', 3)
                  .arg(table.bidirectional ? QStringLiteral("bidirectional")
                                           : QStringLiteral("unidirectional")));
    printLine(QStringLiteral("max |correction|: %1 (correction = −deviation, added to the "
                             "commanded position)")
                  .arg(umWithUnit(table.maxAbsCorrectionUm())));
    printLine(
        QStringLiteral("backlash: mean reversal B̄ = %1").arg(umWithUnit(table.mean_reversal_um)));
    if (writeFile)
        printLine(QStringLiteral("values written: %1, %2")
                      .arg(writtenSign == ValueSign::Correction
                               ? QStringLiteral("correction (−deviation)")
                               : QStringLiteral("error (deviation, actual − target)"),
                           modeName(writtenMode)));
    if (recompensated) {
        printLine(QStringLiteral("change from the active table (%1, %2 points; %3, µm):")
                      .arg(active.layout)
                      .arg(active.table.size())
                      .arg(signName(writtenSign)));
        printLine(table.bidirectional
                      ? QStringLiteral("  position_mm      old+      new+   change+      old-      "
                                       "new-   change-")
                      : QStringLiteral("  position_mm       old       new    change"));
        for (const PointChange& c : recompensated->changes) {
            QString row = QStringLiteral("  %1").arg(c.position_mm, 11, 'f', 3);
            for (double v : {c.old_plus_um, c.new_plus_um, c.changePlusUm()})
                row += QStringLiteral("%1").arg(signedValue(v, writtenSign), 10, 'f', 3);
            if (table.bidirectional)
                for (double v : {c.old_minus_um, c.new_minus_um, c.changeMinusUm()})
                    row += QStringLiteral("%1").arg(signedValue(v, writtenSign), 10, 'f', 3);
            printLine(row);
        }
    }
    printLine(QStringLiteral("uncertainty of the corrections: up to %1 (95 %, k = 2: %2)")
                  .arg(umWithUnit(maxUncertainty),
                       thermal ? QStringLiteral("the cycles' scatter of the mean deviations and "
                                                "the thermal model's prediction interval")
                               : QStringLiteral("the cycles' scatter of the mean deviations")));
    if (pushed) printPush(*plan, *pushed);
    failIfNotApplied();
    return 0;
}

}  // namespace driftlab::cli
