// Sections 1-3 of the acceptance report: the cover, ISO 230-2 and ISO 230-3.
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "core/iso/PositioningStandards.h"
#include "ui/report/ReportDocument.h"

namespace driftlab::ui::report {
namespace {

using namespace driftlab::report;

QString sign(Direction d) {
    return d == Direction::Positive ? QStringLiteral("+") : QStringLiteral("−");
}

/// Tolerances, verdicts, the test's environment and the uncertainty budget.
void addAcceptance(ReportDocument& doc, const iso::PositioningAcceptance& a) {
    doc.subheading(QStringLiteral("Acceptance: %1").arg(iso::toString(a.overall())));
    if (a.decisions.empty()) {
        doc.paragraph(QStringLiteral("The specification sets no tolerance for axis %1: the "
                                     "values and their uncertainties are stated, no verdict.")
                          .arg(a.axis));
    } else {
        doc.paragraph(QStringLiteral(
            "Decision rule of ISO 14253-1: conformance is proven (PASS) when the value plus its "
            "expanded uncertainty U is within the tolerance; non-conformance is proven (FAIL) "
            "when the value minus U is beyond it; otherwise the measurement cannot tell (NOT "
            "PROVEN). Margin = tolerance − (value + U)."));
        Table verdicts{QStringLiteral("iso230-2-verdicts"),
                       {QStringLiteral("Value"), QStringLiteral("Result µm"),
                        QStringLiteral("U µm (k = %1)").arg(a.budget.coverage_k),
                        QStringLiteral("Tolerance µm"), QStringLiteral("Margin µm"),
                        QStringLiteral("Verdict")},
                       {}};
        for (const iso::Decision& d : a.decisions)
            verdicts.rows.push_back({text(d.parameter), number(d.value_um, 3),
                                     number(d.expanded_um, 3), number(d.tolerance_um, 3),
                                     number(d.margin_um, 3), text(iso::toString(d.verdict))});
        doc.table(verdicts);
    }
    doc.subheading(QStringLiteral("Environment and 20 °C"));
    Table environment{
        QStringLiteral("iso230-2-environment"),
        {QStringLiteral("Temperature"), QStringLiteral("Channels"), QStringLiteral("Start °C"),
         QStringLiteral("End °C"), QStringLiteral("Min °C"), QStringLiteral("Max °C"),
         QStringLiteral("Mean °C")},
        {}};
    for (const auto& [name, t] : {std::pair{QStringLiteral("air"), a.environment.air},
                                  std::pair{QStringLiteral("material"), a.environment.material}}) {
        if (t)
            environment.rows.push_back({text(name), text(t->channels.join(QStringLiteral(", "))),
                                        number(t->start_C, 2), number(t->end_C, 2),
                                        number(t->min_C, 2), number(t->max_C, 2),
                                        number(t->mean_C, 2)});
        else
            environment.rows.push_back({text(name), text(QStringLiteral("not logged")), text({}),
                                        text({}), text({}), text({}), text({})});
    }
    doc.table(environment);
    QString normalisation = a.normalisation.description;
    normalisation[0] = normalisation[0].toUpper();
    doc.paragraph(normalisation + QLatin1Char('.'));
    for (const QString& note : a.environment.notes) doc.paragraph(QStringLiteral("Note: ") + note);
    doc.subheading(QStringLiteral("Uncertainty budget (ISO 230-2 annex A, ISO/TR 230-9)"));
    doc.paragraph(QStringLiteral("Standard uncertainties over the measured length %1 mm; sensor "
                                 "accuracies ±a count as a/√3. E, M and A take every "
                                 "contributor; R and B, which compare readings at one target, "
                                 "take the device's length-independent part and the "
                                 "environmental variation error.")
                      .arg(a.budget.conditions.length_mm, 0, 'f', 1));
    Table budget{QStringLiteral("iso230-2-uncertainty"),
                 {QStringLiteral("Contributor"), QStringLiteral("u µm"), QStringLiteral("From")},
                 {}};
    for (const iso::UncertaintyContribution& c : a.budget.contributions)
        budget.rows.push_back({text(c.name), number(c.standard_um, 3), text(c.equation)});
    doc.table(budget);
    Table expanded{QStringLiteral("iso230-2-expanded-uncertainty"),
                   {QStringLiteral("Value"), QStringLiteral("u_c µm"),
                    QStringLiteral("U µm (k = %1)").arg(a.budget.coverage_k)},
                   {}};
    for (const iso::ParameterUncertainty& p : a.budget.parameters)
        expanded.rows.push_back(
            {text(p.parameter), number(p.combined_um, 3), number(p.expanded_um, 3)});
    doc.table(expanded);
    for (const QString& note : a.budget.notes)
        doc.paragraph(QStringLiteral("Note: ") + note + QLatin1Char('.'));
    for (const QString& note : a.notes)
        doc.paragraph(QStringLiteral("Note: ") + note + QLatin1Char('.'));
}

/// The drift figures of a run against their tolerances, when it has any.
void addDriftVerdicts(ReportDocument& doc, const DriftSection& s, const QString& run) {
    const auto found = s.decisions.find(run);
    if (found == s.decisions.end()) return;
    Table table{
        QStringLiteral("iso230-3-verdicts-") + run,
        {QStringLiteral("Figure"), QStringLiteral("Result µm"), QStringLiteral("U µm"),
         QStringLiteral("Tolerance µm"), QStringLiteral("Margin µm"), QStringLiteral("Verdict")},
        {}};
    for (const iso::Decision& d : found->second)
        table.rows.push_back({text(d.parameter), number(d.value_um, 3), number(d.expanded_um, 3),
                              number(d.tolerance_um, 3), number(d.margin_um, 3),
                              text(iso::toString(d.verdict))});
    doc.paragraph(QStringLiteral("Run %1 against the specification (ISO 14253-1, U from the "
                                 "device's length-independent part and the EVE):")
                      .arg(run));
    doc.table(table);
}

/// The tolerance of A, for the lines on the ISO 230-2 plot.
std::optional<double> accuracyTolerance(const PositioningSection& s) {
    if (!s.acceptance) return std::nullopt;
    for (const iso::Decision& d : s.acceptance->decisions)
        if (d.parameter == QLatin1String("A")) return d.tolerance_um;
    return std::nullopt;
}

QString stabilised(double time_s) {
    return std::isnan(time_s) ? QStringLiteral("not stabilised")
                              : QStringLiteral("%1 s").arg(time_s, 0, 'f', 0);
}

/// The same readings by every positioning standard, a column each: what a
/// lab's laser software would print for each (docs/standards.md).
void addStandardsCompared(ReportDocument& doc, const iso::StandardsComparison& c) {
    if (!c.ok() || c.evaluations.empty()) return;
    doc.subheading(QStringLiteral("Standards compared (µm)"));
    Table table{QStringLiteral("iso230-2-standards"),
                {QStringLiteral("Symbol"), QStringLiteral("Key"), QStringLiteral("Quantity")},
                {}};
    for (const iso::StandardEvaluation& e : c.evaluations)
        table.header << iso::standardTitle(e.standard);
    for (const iso::StandardValue* row : iso::comparisonRows(c)) {
        std::vector<Cell> cells{text(row->symbol), text(row->key), text(row->meaning)};
        for (const iso::StandardEvaluation& e : c.evaluations) {
            const iso::StandardValue* v = e.value(row->key);
            cells.push_back(v ? number(v->value_um, 3) : text(QStringLiteral("-")));
        }
        table.rows.push_back(std::move(cells));
    }
    doc.table(table);
    QStringList definitions;
    for (const iso::StandardEvaluation& e : c.evaluations)
        definitions << iso::standardTitle(e.standard) + QStringLiteral(": ") + e.definitions;
    doc.paragraph(QStringLiteral("\"-\": not defined by that standard. ") +
                  definitions.join(QStringLiteral(". ")) + QLatin1Char('.'));
    QStringList leftOut;
    for (const iso::LeftOutStandard& s : iso::leftOutStandards())
        leftOut << s.title + QStringLiteral(" (") + s.why + QLatin1Char(')');
    doc.paragraph(QStringLiteral("Not evaluated: ") + leftOut.join(QStringLiteral("; ")) +
                  QLatin1Char('.'));
}

}  // namespace

void addCover(ReportDocument& doc, const AcceptanceReportData& data) {
    const Cover& c = data.cover;
    doc.titleBlock(QStringLiteral("Acceptance report"));
    doc.paragraph(QStringLiteral("Thermal test campaign “%1”").arg(c.campaign));
    Table facts{QStringLiteral("cover"), {QStringLiteral("Item"), QStringLiteral("Value")}, {}};
    const std::pair<QString, QString> rows[] = {
        {QStringLiteral("Machine"), c.machine},
        {QStringLiteral("Axis"), c.axis.isEmpty() ? QStringLiteral("not given") : c.axis},
        {QStringLiteral("Controller"),
         c.controller.isEmpty() ? QStringLiteral("not given") : c.controller},
        {QStringLiteral("Campaign"), c.campaign},
        {QStringLiteral("Campaign dates"), c.campaign_dates},
        {QStringLiteral("Report date"), c.report_date},
        {QStringLiteral("Operator"), c.operator_name},
        {QStringLiteral("DriftLab version"), c.version}};
    for (const auto& [item, value] : rows) facts.rows.push_back({text(item), text(value)});
    doc.table(facts);
    doc.subheading(QStringLiteral("Runs"));
    Table runs{QStringLiteral("runs"),
               {QStringLiteral("Run"), QStringLiteral("Kind"), QStringLiteral("Description")},
               {}};
    for (const RunLine& r : c.runs)
        runs.rows.push_back({text(r.id), text(r.kind), text(r.description)});
    doc.table(runs);
    doc.paragraph(QStringLiteral(
        "Contents: 1 ISO 230-2 positioning accuracy and repeatability; 2 ISO 230-3 thermal "
        "drift; 3 model comparison (cross-state matrix); 4 diagnosis of what the thermal "
        "simulation misses; 5 pitch-error compensation. Units: position mm, deviation and "
        "drift µm, time s. Sign: deviation = actual − target (ISO 230-2); a correction is "
        "−deviation, added to the commanded position."));
}

void addIso230_2(ReportDocument& doc, const PositioningSection& s) {
    if (s.not_applicable.isEmpty()) doc.pageBreak();  // a one-line section shares a page
    doc.heading(QStringLiteral("1 ISO 230-2: accuracy and repeatability of positioning"));
    if (!s.not_applicable.isEmpty()) {
        doc.paragraph(QStringLiteral("Not applicable: ") + s.not_applicable + QLatin1Char('.'));
        return;
    }
    const iso::Evaluation& e = s.evaluation;
    const double k = e.settings.coverage_factor;
    doc.paragraph(QStringLiteral("%1 evaluation of run %2: %3 targets, %4 cycles. Coverage "
                                 "factor k = %5 (R↑ᵢ = %6·s↑ᵢ, A from x̄ ± %5·s). ↑ is the + "
                                 "approach, ↓ the − approach; deviation = actual − target, µm.%7")
                      .arg(iso::toString(e.settings.edition), s.run_id)
                      .arg(e.targets.size())
                      .arg(e.cycles)
                      .arg(k)
                      .arg(2 * k)
                      .arg(s.run_note.isEmpty()
                               ? QString()
                               : QStringLiteral(" Note: ") + s.run_note + QLatin1Char('.')));
    doc.subheading(
        QStringLiteral("Axis values (%1, k = %2)").arg(iso::toString(e.settings.edition)).arg(k));
    const iso::AxisResult& a = e.axis;
    Table axis{QStringLiteral("iso230-2-axis"),
               {QStringLiteral("Symbol"), QStringLiteral("Key"), QStringLiteral("Quantity"),
                QStringLiteral("Value µm")},
               {}};
    for (const iso::AxisValue& v : iso::axisValues())
        axis.rows.push_back({text(QString::fromUtf8(v.symbol)), text(QString::fromUtf8(v.key)),
                             text(QString::fromUtf8(v.meaning)), number(a.*v.value, 3)});
    doc.table(axis);
    for (const QString& why : e.skipped) doc.paragraph(QStringLiteral("Not determined: ") + why);
    if (s.acceptance) addAcceptance(doc, *s.acceptance);
    if (!s.acceptance_error.isEmpty())
        doc.paragraph(QStringLiteral("Acceptance not evaluated: ") + s.acceptance_error +
                      QLatin1Char('.'));
    if (e.warnings.isEmpty()) doc.paragraph(QStringLiteral("Warnings of the evaluation: none."));
    for (const QString& w : e.warnings) doc.paragraph(QStringLiteral("Warning: ") + w);
    doc.plot({QStringLiteral("iso230-2"),
              QStringLiteral("Mean positional deviation x̄↑, x̄↓ ± %1s over the target position, "
                             "run %2")
                  .arg(k)
                  .arg(s.run_id),
              e,
              {},
              {},
              accuracyTolerance(s)});
    doc.subheading(QStringLiteral("Per target (µm)"));
    Table targets{
        QStringLiteral("iso230-2-targets"),
        {QStringLiteral("Target mm"), QStringLiteral("x̄↑"), QStringLiteral("x̄↓"),
         QStringLiteral("x̄"), QStringLiteral("s↑"), QStringLiteral("s↓"), QStringLiteral("Bᵢ"),
         QStringLiteral("R↑ᵢ"), QStringLiteral("R↓ᵢ"), QStringLiteral("Rᵢ")},
        {}};
    for (const iso::TargetResult& t : e.targets)
        targets.rows.push_back({number(t.target_mm, 3), number(t.mean_up_um, 3),
                                number(t.mean_down_um, 3), number(t.mean_um, 3),
                                number(t.s_up_um, 3), number(t.s_down_um, 3),
                                number(t.reversal_um, 3), number(t.r_up_um, 3),
                                number(t.r_down_um, 3), number(t.r_um, 3)});
    doc.table(targets);
    addStandardsCompared(doc, s.standards);
}

void addIso230_3(ReportDocument& doc, const DriftSection& s) {
    if (s.not_applicable.isEmpty()) doc.pageBreak();  // a one-line section shares a page
    doc.heading(QStringLiteral("2 ISO 230-3: thermal drift"));
    if (!s.not_applicable.isEmpty()) {
        doc.paragraph(QStringLiteral("Not applicable: ") + s.not_applicable + QLatin1Char('.'));
        return;
    }
    for (const QString& e : s.errors) doc.paragraph(QStringLiteral("Not evaluated: ") + e);
    const iso::DriftSettings& settings =
        !s.axis_runs.empty() ? s.axis_runs.front().settings : s.probe_runs.front().settings;
    doc.paragraph(QStringLiteral("Drift = deviation − deviation at the cold reference cycle 0 "
                                 "(moving runs), value − the probe's first sample (spindle and "
                                 "ETVE runs). Stabilised: the drift varies by less than %1 µm "
                                 "over every %2 s window from then on (DriftLab's criterion).")
                      .arg(settings.tolerance_um)
                      .arg(settings.window_s));
    doc.subheading(QStringLiteral("Moving runs"));
    if (!s.axis_not_applicable.isEmpty()) doc.paragraph(s.axis_not_applicable + QLatin1Char('.'));
    for (const iso::AxisDriftEvaluation& e : s.axis_runs) {
        const iso::TargetDrift& max = e.targets[std::size_t(e.max_index)];
        doc.paragraph(
            QStringLiteral("Run %1: max drift %2 µm at %3 mm (%4), t = %5 s; %6.")
                .arg(e.run_id)
                .arg(e.max_drift_um, 0, 'f', 2)
                .arg(max.target_mm)
                .arg(sign(max.direction))
                .arg(max.drift.max_drift_time_s, 0, 'f', 0)
                .arg(std::isnan(e.stabilised_time_s)
                         ? QStringLiteral("not stabilised within the run")
                         : QStringLiteral("stabilised at %1 s").arg(e.stabilised_time_s)));
        CurvePlot plot{QStringLiteral("Run %1: drift at each target, + approach").arg(e.run_id),
                       QStringLiteral("Time (s)"),
                       QStringLiteral("Drift (µm)"),
                       {}};
        for (const iso::TargetDrift& t : e.targets)
            if (t.direction == Direction::Positive)
                plot.curves.push_back({QStringLiteral("%1 mm").arg(t.target_mm), t.drift.time_s,
                                       t.drift.drift_um, false});
        doc.plot({QStringLiteral("iso230-3-") + e.run_id,
                  QStringLiteral("Drift against time per target, run %1").arg(e.run_id),
                  {},
                  plot,
                  {},
                  {}});
        Table table{
            QStringLiteral("iso230-3-") + e.run_id,
            {QStringLiteral("Target mm"), QStringLiteral("Dir"), QStringLiteral("Max drift µm"),
             QStringLiteral("At s"), QStringLiteral("Range µm"), QStringLiteral("Final µm"),
             QStringLiteral("Stabilised")},
            {}};
        for (const iso::TargetDrift& t : e.targets)
            table.rows.push_back(
                {number(t.target_mm, 3), text(sign(t.direction)), number(t.drift.max_drift_um, 3),
                 number(t.drift.max_drift_time_s, 0), number(t.drift.range_um, 3),
                 number(t.drift.final_drift_um, 3), text(stabilised(t.drift.stabilised_time_s))});
        doc.table(table);
        addDriftVerdicts(doc, s, e.run_id);
    }
    doc.subheading(QStringLiteral("Spindle and ETVE runs"));
    if (!s.probe_not_applicable.isEmpty()) doc.paragraph(s.probe_not_applicable + QLatin1Char('.'));
    for (const iso::ProbeDriftEvaluation& e : s.probe_runs) {
        CurvePlot plot{QStringLiteral("Run %1: probe drifts").arg(e.run_id),
                       QStringLiteral("Time (s)"),
                       QStringLiteral("Drift (µm)"),
                       {}};
        Table table{
            QStringLiteral("iso230-3-") + e.run_id,
            {QStringLiteral("Probe"), QStringLiteral("Role"), QStringLiteral("Max drift µm"),
             QStringLiteral("At s"), QStringLiteral("Range µm"), QStringLiteral("Max tilt µrad"),
             QStringLiteral("Stabilised")},
            {}};
        for (const iso::ProbeDrift& p : e.probes) {
            plot.curves.push_back({p.channel_id, p.drift.time_s, p.drift.drift_um, false});
            table.rows.push_back(
                {text(p.channel_id), text(toString(p.role)), number(p.drift.max_drift_um, 3),
                 number(p.drift.max_drift_time_s, 0), number(p.drift.range_um, 3),
                 text(QStringLiteral("—")), text(stabilised(p.drift.stabilised_time_s))});
        }
        for (const iso::TiltDrift& t : e.tilts)
            table.rows.push_back({text(QStringLiteral("tilt %1 (%2−%3)").arg(t.name, t.to, t.from)),
                                  text(QStringLiteral("tilt")), number(t.drift.max_drift_um, 3),
                                  number(t.drift.max_drift_time_s, 0), number(t.drift.range_um, 3),
                                  number(t.max_tilt_urad, 2),
                                  text(stabilised(t.drift.stabilised_time_s))});
        doc.paragraph(
            QStringLiteral("Run %1 (%2): %3.")
                .arg(e.run_id, toString(e.kind),
                     std::isnan(e.stabilised_time_s)
                         ? QStringLiteral("not stabilised within the run")
                         : QStringLiteral("stabilised at %1 s").arg(e.stabilised_time_s)));
        doc.plot({QStringLiteral("iso230-3-") + e.run_id, plot.title, {}, plot, {}, {}});
        doc.table(table);
        addDriftVerdicts(doc, s, e.run_id);
        for (const QString& note : e.notes) doc.paragraph(QStringLiteral("Note: ") + note);
    }
}

}  // namespace driftlab::ui::report
