// iso230-3: ISO 230-3 thermal drift of a campaign's runs: each target of a
// moving feed-axis run, each probe of a spindle or ETVE run (docs/iso230-3.md).
#include <QJsonArray>

#include "app/cli/CliCommon.h"
#include "app/cli/IsoOptions.h"
#include "core/iso/AcceptanceJson.h"
#include "core/iso/DriftAcceptance.h"
#include "core/iso/Iso230_3.h"

namespace driftlab::cli {
namespace {

bool hasAxisDrift(const Run& run) {
    return isFeedAxisRun(run.kind) && !run.positioning.empty();
}
bool hasProbeDrift(const Run& run) {
    return run.kind == RunKind::Spindle || run.kind == RunKind::Etve;
}

/// --run R, else every moving run with readings and every spindle and ETVE run.
std::vector<const Run*> chooseRuns(const Campaign& campaign, const QString& wanted) {
    std::vector<const Run*> runs;
    QStringList ids;
    for (const Run& run : campaign.runs) {
        ids << run.id;
        if (wanted.isEmpty()
                ? (run.kind == RunKind::Moving && hasAxisDrift(run)) || hasProbeDrift(run)
                : run.id == wanted)
            runs.push_back(&run);
    }
    if (!wanted.isEmpty() && runs.empty())
        throw CliError(QStringLiteral("--run: no run '%1' in the campaign (runs: %2)")
                           .arg(wanted, ids.join(QStringLiteral(", "))),
                       2);
    if (runs.empty())
        throw CliError(
            QStringLiteral("no run of the campaign is a moving run with positioning "
                           "readings, a spindle run or an ETVE run"));
    if (!hasAxisDrift(*runs.front()) && !hasProbeDrift(*runs.front()))
        throw CliError(QStringLiteral("run %1 (%2) has no drift to evaluate: it is neither a "
                                      "feed-axis run with positioning readings nor a spindle or "
                                      "ETVE run")
                           .arg(wanted, toString(runs.front()->kind)));
    return runs;
}

QString stabilisedText(const iso::DriftSeries& s) {
    return s.stabilised() ? QStringLiteral("%1 s").arg(s.stabilised_time_s)
                          : QStringLiteral("not stabilised");
}
QString sign(Direction d) {
    return d == Direction::Positive ? QStringLiteral("+") : QStringLiteral("-");
}

/// A difference of readings given to 0.01 µm prints as 11.069999999999999:
/// rounded to 1 pm, far below any probe's or interferometer's resolution.
double picometres(double value_um) {
    return std::round(value_um * 1e6) / 1e6;
}

QJsonObject seriesJson(const iso::DriftSeries& s) {
    return {{QStringLiteral("max_drift_um"), picometres(s.max_drift_um)},
            {QStringLiteral("max_drift_time_s"), s.max_drift_time_s},
            {QStringLiteral("range_um"), picometres(s.range_um)},
            {QStringLiteral("final_drift_um"), picometres(s.final_drift_um)},
            {QStringLiteral("stabilised"), s.stabilised()},
            {QStringLiteral("stabilised_time_s"), jsonNumber(s.stabilised_time_s)}};
}

QJsonObject axisJson(const iso::AxisDriftEvaluation& e) {
    QJsonArray targets;
    for (const iso::TargetDrift& t : e.targets) {
        QJsonObject o = seriesJson(t.drift);
        o[QStringLiteral("target_mm")] = t.target_mm;
        o[QStringLiteral("direction")] = sign(t.direction);
        QJsonArray time_s, drift_um;
        for (std::size_t i = 0; i < t.drift.time_s.size(); ++i) {
            time_s.append(t.drift.time_s[i]);
            drift_um.append(picometres(t.drift.drift_um[i]));
        }
        o[QStringLiteral("time_s")] = time_s;
        o[QStringLiteral("drift_um")] = drift_um;
        targets.append(o);
    }
    // The axis zero and far end, by direction, so that scripts need not search the targets.
    auto end = [&](double at_mm) {
        QJsonObject o{{QStringLiteral("target_mm"), at_mm}};
        for (Direction d : {Direction::Positive, Direction::Negative})
            if (const iso::TargetDrift* t = e.find(at_mm, d)) o[sign(d)] = seriesJson(t->drift);
        return o;
    };
    const iso::TargetDrift& max = e.targets[std::size_t(e.max_index)];
    return {{QStringLiteral("evaluation"), QStringLiteral("moving linear axis")},
            {QStringLiteral("zero"), end(e.zero_mm)},
            {QStringLiteral("far_end"), end(e.far_end_mm)},
            {QStringLiteral("cycles"), e.cycles},
            {QStringLiteral("zero_mm"), e.zero_mm},
            {QStringLiteral("far_end_mm"), e.far_end_mm},
            {QStringLiteral("max_drift_um"), picometres(e.max_drift_um)},
            {QStringLiteral("max_drift_target_mm"), max.target_mm},
            {QStringLiteral("max_drift_direction"), sign(max.direction)},
            {QStringLiteral("max_drift_time_s"), max.drift.max_drift_time_s},
            {QStringLiteral("stabilised"), !std::isnan(e.stabilised_time_s)},
            {QStringLiteral("stabilised_time_s"), jsonNumber(e.stabilised_time_s)},
            {QStringLiteral("targets"), targets},
            {QStringLiteral("warnings"), QJsonArray::fromStringList(e.warnings)}};
}

QJsonObject probesJson(const iso::ProbeDriftEvaluation& e) {
    QJsonArray probes, tilts;
    for (const iso::ProbeDrift& p : e.probes) {
        QJsonObject o = seriesJson(p.drift);
        o[QStringLiteral("channel")] = p.channel_id;
        o[QStringLiteral("role")] = toString(p.role);
        o[QStringLiteral("samples")] = int(p.drift.time_s.size());
        probes.append(o);
    }
    for (const iso::TiltDrift& t : e.tilts) {
        QJsonObject o = seriesJson(t.drift);
        o[QStringLiteral("name")] = t.name;
        o[QStringLiteral("from")] = t.from;
        o[QStringLiteral("to")] = t.to;
        o[QStringLiteral("max_tilt_urad")] = picometres(t.max_tilt_urad);
        o[QStringLiteral("range_urad")] = picometres(t.range_urad);
        tilts.append(o);
    }
    return {{QStringLiteral("evaluation"), QStringLiteral("drift probes")},
            {QStringLiteral("probes"), probes},
            {QStringLiteral("tilts"), tilts},
            {QStringLiteral("stabilised"), !std::isnan(e.stabilised_time_s)},
            {QStringLiteral("stabilised_time_s"), jsonNumber(e.stabilised_time_s)},
            {QStringLiteral("notes"), QJsonArray::fromStringList(e.notes)},
            {QStringLiteral("warnings"), QJsonArray::fromStringList(e.warnings)}};
}

QString row(const QString& head, const iso::DriftSeries& s) {
    return head + QStringLiteral("%1%2%3%4  %5")
                      .arg(umText(s.max_drift_um), 14)
                      .arg(s.max_drift_time_s, 11)
                      .arg(umText(s.range_um), 10)
                      .arg(umText(s.final_drift_um), 10)
                      .arg(stabilisedText(s));
}

QString overall(double stabilised_time_s) {
    return std::isnan(stabilised_time_s)
               ? QStringLiteral("not stabilised within the run")
               : QStringLiteral("stabilised at %1 s").arg(stabilised_time_s);
}

void printAxis(const iso::AxisDriftEvaluation& e, const QString& label) {
    printLine(QStringLiteral("%1: %2 target/direction series, %3 cycles (cycle 0 = cold "
                             "reference); drift = deviation − deviation at cycle 0")
                  .arg(label)
                  .arg(e.targets.size())
                  .arg(e.cycles));
    printLine(
        QStringLiteral(" target_mm dir  max drift µm  at time_s  range µm  final µm  "
                       "stabilised at"));
    for (const iso::TargetDrift& t : e.targets)
        printLine(row(QStringLiteral("%1  %2 ").arg(t.target_mm, 10, 'f', 3).arg(sign(t.direction)),
                      t.drift));
    const iso::TargetDrift& max = e.targets[std::size_t(e.max_index)];
    printLine(QStringLiteral("axis: max drift %1 µm at %2 mm '%3', t = %4 s; %5")
                  .arg(umText(e.max_drift_um))
                  .arg(max.target_mm)
                  .arg(sign(max.direction))
                  .arg(max.drift.max_drift_time_s)
                  .arg(overall(e.stabilised_time_s)));
    for (double at_mm : {e.zero_mm, e.far_end_mm}) {
        QStringList parts;
        for (Direction d : {Direction::Positive, Direction::Negative})
            if (const iso::TargetDrift* t = e.find(at_mm, d))
                parts
                    << QStringLiteral("'%1' max %2 µm").arg(sign(d), umText(t->drift.max_drift_um));
        printLine(QStringLiteral("%1 (%2 mm): %3")
                      .arg(at_mm == e.zero_mm ? QStringLiteral("zero") : QStringLiteral("far end"))
                      .arg(at_mm)
                      .arg(parts.join(QStringLiteral(", "))));
    }
}

void printProbes(const iso::ProbeDriftEvaluation& e, const QString& label) {
    printLine(QStringLiteral("%1: %2 probes; drift = value − the probe's first sample")
                  .arg(label)
                  .arg(e.probes.size()));
    printLine(
        QStringLiteral(" probe      role      max drift µm  at time_s  range µm  final µm  "
                       "stabilised at"));
    for (const iso::ProbeDrift& p : e.probes)
        printLine(
            row(QStringLiteral(" %1%2").arg(p.channel_id, -11).arg(toString(p.role), -7), p.drift));
    for (const iso::TiltDrift& t : e.tilts)
        printLine(
            row(QStringLiteral(" tilt %1 (%2−%3)").arg(t.name, t.to, t.from).leftJustified(18),
                t.drift) +
            QStringLiteral("; max %1 µrad").arg(umText(t.max_tilt_urad)));
    printLine(QStringLiteral("run: %1").arg(overall(e.stabilised_time_s)));
    for (const QString& note : e.notes) printLine(QStringLiteral("note: ") + note);
}

}  // namespace

int iso230_3Command(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption runOption{
        QStringLiteral("run"),
        QStringLiteral("The run to evaluate (default: every moving run with positioning "
                       "readings and every spindle and ETVE run)."),
        QStringLiteral("R")};
    const QCommandLineOption window{
        QStringLiteral("window-s"),
        QStringLiteral("W of the stabilisation criterion, s (default 600, DriftLab's choice)."),
        QStringLiteral("W"), QStringLiteral("600")};
    const QCommandLineOption tolerance{
        QStringLiteral("tolerance-um"),
        QStringLiteral("D of the stabilisation criterion: the drift must vary by less than D "
                       "over every window W from then on, µm (default 1, DriftLab's choice)."),
        QStringLiteral("D"), QStringLiteral("1")};
    const QCommandLineOption distance{
        QStringLiteral("probe-distance-mm"),
        QStringLiteral("Spindle runs: distance between the two x (and two y) probes along the "
                       "mandrel; gives tilts A and B (none without it)."),
        QStringLiteral("L")};
    const QCommandLineOption specOption = acceptanceSpecOption();
    parseArguments(parser, args,
                   campaignSourceOptions()
                       << runOption << window << tolerance << distance << specOption,
                   campaignSourceArguments());
    iso::DriftSettings settings;
    settings.window_s = positiveNumberOption(parser, window);
    settings.tolerance_um = positiveNumberOption(parser, tolerance);
    if (parser.isSet(distance)) settings.probe_distance_mm = positiveNumberOption(parser, distance);

    const Campaign campaign = loadCampaignSource(parser);
    const auto spec = acceptanceSpecification(parser, campaign);
    // Chosen before anything is printed: a bad --run leaves stdout empty.
    const std::vector<const Run*> chosen = chooseRuns(campaign, parser.value(runOption));
    QJsonArray runs;
    const bool json = parser.isSet(QStringLiteral("json"));
    if (!json)
        printLine(QStringLiteral("ISO 230-3 thermal drift of %1; stabilised = the drift varies by "
                                 "less than %2 µm over every %3 s window from then on "
                                 "(DriftLab's criterion)")
                      .arg(campaign.name)
                      .arg(settings.tolerance_um)
                      .arg(settings.window_s));
    for (const Run* run : chosen) {
        const QString label = QStringLiteral("run %1 (%2)").arg(run->id, toString(run->kind));
        QJsonObject o;
        iso::DriftFigures figures;
        if (hasAxisDrift(*run)) {
            const iso::AxisDriftEvaluation e = iso::evaluateAxisDrift(*run, settings);
            if (!e.ok()) throw CliError(e.error);
            printWarnings(e.warnings);
            if (!json) printLine(QString()), printAxis(e, label);
            o = axisJson(e);
            figures = iso::driftFigures(e);
        } else {
            const iso::ProbeDriftEvaluation e = iso::evaluateProbeDrift(campaign, *run, settings);
            if (!e.ok()) throw CliError(e.error);
            printWarnings(e.warnings);
            if (!json) printLine(QString()), printProbes(e, label);
            o = probesJson(e);
            figures = iso::driftFigures(e);
        }
        if (spec) {
            const auto decisions = iso::driftDecisions(*spec, campaign.machine.axis, figures);
            o[QStringLiteral("acceptance")] =
                QJsonObject{{QStringLiteral("decision_rule"), iso::decisionRuleText()},
                            {QStringLiteral("decisions"), iso::decisionsJson(decisions)}};
            if (!json && !decisions.empty()) {
                printLine(QStringLiteral("acceptance of the drift figures (%1):")
                              .arg(iso::decisionRuleText()));
                for (const QString& line : iso::decisionsText(decisions)) printLine(line);
            }
        }
        o[QStringLiteral("run")] = run->id;
        o[QStringLiteral("kind")] = toString(run->kind);
        runs.append(o);
    }
    if (json)
        printJson(
            {{QStringLiteral("standard"), QStringLiteral("ISO 230-3")},
             {QStringLiteral("campaign"), campaign.name},
             {QStringLiteral("window_s"), settings.window_s},
             {QStringLiteral("tolerance_um"), settings.tolerance_um},
             {QStringLiteral("probe_distance_mm"),
              settings.probe_distance_mm ? QJsonValue(*settings.probe_distance_mm) : QJsonValue()},
             {QStringLiteral("unit"), QStringLiteral("µm")},
             {QStringLiteral("runs"), runs}});
    return 0;
}

}  // namespace driftlab::cli
