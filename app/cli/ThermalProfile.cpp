#include "app/cli/ThermalProfile.h"

#include <QJsonObject>
#include <algorithm>
#include <cmath>

#include "app/cli/CliCommon.h"
#include "core/models/ModelFactory.h"

namespace driftlab::cli {
namespace {

const QCommandLineOption kModel{
    QStringLiteral("model"),
    QStringLiteral("Add this model's thermal error at the state of --at to the cold error."),
    QStringLiteral("NAME")};
const QCommandLineOption kTrain{QStringLiteral("train"),
                                QStringLiteral("Runs the model is fitted on (default: the run of "
                                               "--at is not among them; the first other run)."),
                                QStringLiteral("R,..")};
const QCommandLineOption kReference{
    QStringLiteral("reference"),
    QStringLiteral("sinumerik-temp, isg-temp: the line's reference position (default: the "
                   "screw's fixed end)."),
    QStringLiteral("MM")};
const QCommandLineOption kAt{
    QStringLiteral("at"),
    QStringLiteral("The thermal state: a run and a time in it, RUN@SECONDS (e.g. S3@3600)."),
    QStringLiteral("RUN@S")};

const QCommandLineOption kForce{
    QStringLiteral("force"),
    QStringLiteral("Use the model even when it does worse than no compensation on its own "
                   "cross-validation (refused without it: it would make the machine worse).")};

}  // namespace

QList<QCommandLineOption> thermalProfileOptions() {
    return {kModel, kTrain, kAt, kReference, kForce};
}

const QCommandLineOption& forceOption() {
    return kForce;
}

void refuseHarm(const QCommandLineParser& parser, const models::Validation& validation,
                const QString& what) {
    if (!validation.worseThanNone()) return;
    const QString why = validation.harmReason(what);
    if (!parser.isSet(kForce)) throw CliError(why + QStringLiteral("; --force overrides"));
    printWarnings({why + QStringLiteral(" (used anyway: --force)")});
}

bool wantsThermalProfile(const QCommandLineParser& parser) {
    return parser.isSet(kModel) || parser.isSet(kAt);
}

ThermalProfile thermalProfile(const QCommandLineParser& parser, const Campaign& campaign,
                              double from_mm, double to_mm) {
    if (!parser.isSet(kModel) || !parser.isSet(kAt))
        throw CliError(QStringLiteral("a thermal state needs both --model and --at RUN@SECONDS"),
                       2);
    const QString at = parser.value(kAt);
    const QStringList parts = at.split(QLatin1Char('@'));
    bool ok = parts.size() == 2;
    const double time_s = ok ? parts[1].toDouble(&ok) : 0;
    if (!ok || !std::isfinite(time_s) || time_s < 0)
        throw CliError(
            QStringLiteral("--at: '%1' is not RUN@SECONDS (a run and a time in it)").arg(at), 2);
    compensation::ThermalStateOptions options;
    options.model = parser.value(kModel);
    options.state_run = parts[0];
    options.time_s = time_s;
    options.train_runs = runList(parser.value(kTrain));
    refuseOverlappingRuns(options.train_runs, {options.state_run});
    if (options.train_runs.isEmpty())
        if (const QString first = compensation::defaultTrainingRun(campaign, options.state_run);
            !first.isEmpty())
            options.train_runs << first;
    if (options.train_runs.isEmpty())
        throw CliError(QStringLiteral("--train: no run to fit the model on"), 2);

    if (!models::makeModel(options.model))
        throw CliError(QStringLiteral("--model: '%1' is not a model (%2)")
                           .arg(options.model, models::fitModelNames().join(", ")),
                       2);
    options.progress = printProgress;
    compensation::ThermalStateFit fit;
    try {
        fit = compensation::fitThermalState(campaign, options);
    } catch (const ServiceError& e) {
        if (e.kind != ServiceError::Kind::BadRequest) throw;
        throw CliError(QStringLiteral("--at: ") + e.message(), 2);  // the state's run is too short
    }
    refuseHarm(parser, fit.validation, QStringLiteral("--model %1").arg(options.model));
    if (const QString none = fit.choseNone(); !none.isEmpty())
        throw CliError(QStringLiteral("--model auto: %1; the table would carry no thermal part: "
                                      "leave out --model and --at for the cold table")
                           .arg(none));
    printWarnings(models::gapLines(fit.gaps));
    try {
        return compensation::thermalProfile(fit, from_mm, to_mm);
    } catch (const ServiceError& e) {
        throw CliError(QStringLiteral("--at %1: ").arg(at) + e.message());
    }
}

bool isTemperatureLineFormat(const QString& format) {
    return format == QLatin1String("sinumerik-temp") || format == QLatin1String("isg-temp");
}

int writeTemperatureLine(const QCommandLineParser& parser, const ThermalProfile& profile,
                         const QString& format, const QString& source) {
    const double reference_mm =
        parser.isSet(kReference) ? numberOption(parser, kReference) : profile.fixed_end_mm;
    const compensation::ErrorLine line = compensation::thermalErrorLine(profile, reference_mm);
    const QString axis = parser.value(QStringLiteral("axis"));
    const compensation::ExportResult exported =
        format == QLatin1String("isg-temp")
            ? compensation::exportIsgTemperatureLine(line)
            : compensation::exportSinumerikTemperatureLine(
                  line, axis.isEmpty() ? QStringLiteral("AX1") : axis);
    if (!exported.ok()) throw CliError(format + QStringLiteral(": ") + exported.error);
    const QString out = parser.value(QStringLiteral("out"));
    writeFileAtomically(out, exported.text);
    printWarnings(exported.warnings);
    const QJsonObject lineJson{{QStringLiteral("reference_mm"), line.reference_mm},
                               {QStringLiteral("offset_um"), line.offset_um},
                               {QStringLiteral("slope_um_per_m"), line.slope_um_per_m},
                               {QStringLiteral("residual_rms_um"), line.residual_rms_um},
                               {QStringLiteral("residual_peak_um"), line.residual_peak_um}};
    if (parser.isSet(QStringLiteral("json"))) {
        printJson({{QStringLiteral("source"), source},
                   {QStringLiteral("format"), format},
                   {QStringLiteral("out"), out},
                   {QStringLiteral("thermal"), profile.description},
                   {QStringLiteral("line"), lineJson},
                   {QStringLiteral("sign"),
                    QStringLiteral("offset and slope of the error (actual - target)")}});
        return 0;
    }
    printLine(QStringLiteral("%1 straight-line temperature compensation from %2 → %3")
                  .arg(format, source, out));
    printLine(QStringLiteral("error %1 µm at %2 mm, slope %3 µm/m (error = actual − target); the "
                             "line leaves %4 µm RMS, %5 µm peak of the thermal error from %6 to "
                             "%7 mm")
                  .arg(line.offset_um, 0, 'f', 3)
                  .arg(line.reference_mm, 0, 'f', 3)
                  .arg(line.slope_um_per_m, 0, 'f', 3)
                  .arg(line.residual_rms_um, 0, 'f', 3)
                  .arg(line.residual_peak_um, 0, 'f', 3)
                  .arg(profile.from_mm, 0, 'f', 1)
                  .arg(profile.to_mm, 0, 'f', 1));
    return 0;
}

}  // namespace driftlab::cli
