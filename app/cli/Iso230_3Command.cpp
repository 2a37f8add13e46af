// iso230-3: ISO 230-3 thermal drift of a campaign's runs: each target of a
// moving feed-axis run, each probe of a spindle or ETVE run (docs/iso230-3.md).
#include <QJsonArray>

#include "app/cli/CliCommon.h"
#include "app/cli/IsoOptions.h"
#include "core/iso/AcceptanceJson.h"
#include "core/iso/DriftAcceptance.h"
#include "core/iso/Iso230_3.h"
#include "core/iso/Iso230_3Json.h"

namespace driftlab::cli {
namespace {

using iso::hasAxisDrift;
using iso::hasProbeDrift;

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
        throw CliError(iso::evaluateRunDrift(campaign, *runs.front(), {}).error);
    return runs;
}

QString stabilisedText(const iso::DriftSeries& s) {
    return s.stabilised() ? QStringLiteral("%1 s").arg(s.stabilised_time_s)
                          : QStringLiteral("not stabilised");
}
QString sign(Direction d) {
    return d == Direction::Positive ? QStringLiteral("+") : QStringLiteral("-");
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
        const iso::RunDrift drift = iso::evaluateRunDrift(campaign, *run, settings);
        if (!drift.ok()) throw CliError(drift.error);
        printWarnings(drift.warnings());
        if (!json) {
            printLine(QString());
            if (drift.axis)
                printAxis(*drift.axis, label);
            else
                printProbes(*drift.probes, label);
        }
        QJsonObject o = iso::runDriftJson(drift);
        const iso::DriftFigures figures = drift.figures();
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
