#include "app/cli/ThermalProfile.h"

#include <QJsonObject>
#include <algorithm>
#include <cmath>

#include "app/cli/CliCommon.h"
#include "core/compensation/TemperatureCompensationLine.h"
#include "core/models/AutoModel.h"
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

/// Where the profile is evaluated: one point per millimetre at most, at least
/// 64, then linear in between (the heat-transfer model simulates the whole run
/// per call, so it is called once).
constexpr int kProfilePoints = 257;

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
    const QString why = QStringLiteral(
                            "%1 does worse than no compensation where it was not "
                            "fitted (%2, %3): it would make the machine worse")
                            .arg(what, validation.describe(), validation.folds);
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
    const QString stateRun = parts[0];
    QStringList train = runList(parser.value(kTrain));
    refuseOverlappingRuns(train, {stateRun});
    if (train.isEmpty())
        for (const Run& run : campaign.runs)
            if (run.id != stateRun && isFeedAxisRun(run.kind) && !run.positioning.empty()) {
                train << run.id;
                break;
            }
    if (train.isEmpty()) throw CliError(QStringLiteral("--train: no run to fit the model on"), 2);

    if (!models::makeModel(parser.value(kModel)))
        throw CliError(QStringLiteral("--model: '%1' is not a model (%2)")
                           .arg(parser.value(kModel), models::fitModelNames().join(", ")),
                       2);
    models::DatasetResult data = models::buildDataset(campaign, train + QStringList{stateRun});
    if (!data.ok()) throw CliError(data.error);
    const models::RunData state = data.runs.back();
    data.runs.pop_back();
    double end_s = 0;
    for (const auto& o : state.observations) end_s = std::max(end_s, o.time_s);
    if (!state.motion.empty()) end_s = std::max(end_s, state.motion.back().end_s);
    if (time_s > end_s)
        throw CliError(QStringLiteral("--at: run %1 ends at %2 s, before %3 s")
                           .arg(stateRun)
                           .arg(end_s)
                           .arg(time_s),
                       2);
    const QString name = parser.value(kModel);
    printProgress(QStringLiteral("fitting ") + name, 0);
    models::ValidatedFit validated = models::fitValidated(name, data.runs);
    printProgress(QStringLiteral("fitting ") + name, 1);
    if (!validated.fit.success) throw CliError(validated.fit.message);
    refuseHarm(parser, validated.validation, QStringLiteral("--model %1").arg(name));
    if (const auto* chooser = dynamic_cast<const models::AutoModel*>(validated.model.get());
        chooser && chooser->chosen() == QLatin1String("none"))
        throw CliError(QStringLiteral("--model auto: %1; the table would carry no thermal part: "
                                      "leave out --model and --at for the cold table")
                           .arg(validated.fit.notes.front().section(QLatin1Char(':'), 0, 0)));
    const models::ThermalErrorModel* model = validated.model.get();
    std::vector<models::DataGap> gaps = models::gapsOf(data.runs);
    gaps.insert(gaps.end(), state.gaps.begin(), state.gaps.end());
    printWarnings(models::gapLines(gaps));

    ThermalProfile profile;
    profile.validation = validated.validation;
    // The state's run beyond the training runs' rises is an extrapolation.
    profile.uncertainty_um = [interval = validated.validation.interval,
                              beyond = models::beyondTraining(data.runs, state)](double x) {
        return interval.known() ? interval.halfWidthAt(x, beyond) : 0.0;
    };
    profile.from_mm = from_mm;
    profile.to_mm = to_mm;
    profile.fixed_end_mm = state.fixedEnd_mm();
    std::vector<models::PredictionPoint> points;
    for (int i = 0; i < kProfilePoints; ++i)
        points.push_back({time_s, from_mm + (to_mm - from_mm) * i / (kProfilePoints - 1)});
    const models::Prediction predicted = model->predict(state, points);
    if (!predicted.ok()) throw CliError(QStringLiteral("--at %1: ").arg(at) + predicted.error);
    std::vector<double> x_mm, e_um;
    for (std::size_t i = 0; i < points.size(); ++i) {
        x_mm.push_back(points[i].position_mm);
        e_um.push_back(predicted.error_um[i]);
    }
    profile.error_um = [x_mm, e_um](double x) {
        if (x <= x_mm.front()) return e_um.front();
        if (x >= x_mm.back()) return e_um.back();
        const auto hi = std::size_t(std::upper_bound(x_mm.begin(), x_mm.end(), x) - x_mm.begin());
        const double f = (x - x_mm[hi - 1]) / (x_mm[hi] - x_mm[hi - 1]);
        return e_um[hi - 1] + f * (e_um[hi] - e_um[hi - 1]);
    };
    profile.description = QStringLiteral("%1 fitted on %2, at %3 t = %4 s")
                              .arg(model->name(), train.join(QLatin1Char(',')), stateRun)
                              .arg(time_s);
    return profile;
}

bool isTemperatureLineFormat(const QString& format) {
    return format == QLatin1String("sinumerik-temp") || format == QLatin1String("isg-temp");
}

int writeTemperatureLine(const QCommandLineParser& parser, const ThermalProfile& profile,
                         const QString& format, const QString& source) {
    std::vector<double> x_mm, e_um;
    for (int i = 0; i < kProfilePoints; ++i) {
        x_mm.push_back(profile.from_mm +
                       (profile.to_mm - profile.from_mm) * i / (kProfilePoints - 1));
        e_um.push_back(profile.error_um(x_mm.back()));
    }
    const double reference_mm =
        parser.isSet(kReference) ? numberOption(parser, kReference) : profile.fixed_end_mm;
    const compensation::ErrorLine line = compensation::fitErrorLine(x_mm, e_um, reference_mm);
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
