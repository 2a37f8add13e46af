// Sections 4-6 of the acceptance report: model comparison, diagnosis and
// compensation; and the report as a whole.
#include <cmath>

#include "core/models/DataGaps.h"
#include "ui/plots/DiagnosisPlots.h"
#include "ui/report/ReportDocument.h"

namespace driftlab::ui::report {
namespace {

using namespace driftlab::report;

void notApplicable(ReportDocument& doc, const QString& why) {
    doc.paragraph(QStringLiteral("Not applicable: ") + why + QLatin1Char('.'));
}

/// What the section's fits made of the holes in the log: a line per hole left
/// out, one for those bridged (as `fit` and `diagnose` print them).
void addGaps(ReportDocument& doc, const std::vector<models::DataGap>& gaps) {
    for (QString line : models::gapLines(gaps)) {
        line[0] = line[0].toUpper();
        doc.paragraph(line + QLatin1Char('.'));
    }
}

}  // namespace

Cell number(double value, int decimals) {
    if (!std::isfinite(value)) return {QStringLiteral("n/a"), QString()};
    return {QString::number(value, 'f', decimals), QString::number(value, 'g', 17)};
}

Cell text(const QString& value) {
    return {value, {}};
}

std::vector<const Table*> ReportDocument::tables() const {
    std::vector<const Table*> out;
    for (const Block& b : blocks)
        if (b.kind == Block::Kind::Table) out.push_back(&b.table);
    return out;
}

void addModels(ReportDocument& doc, const ModelSection& s) {
    if (s.not_applicable.isEmpty()) doc.pageBreak();  // a one-line section shares a page
    doc.heading(QStringLiteral("3 Model comparison: cross-state matrix"));
    if (!s.not_applicable.isEmpty()) return notApplicable(doc, s.not_applicable);
    doc.paragraph(QStringLiteral("RMS residual (µm) on each run (columns) of the model fitted on "
                                 "each run alone (rows). In brackets on the diagonal: %1; off "
                                 "it: held-out scores, the headline comparison.")
                      .arg(s.diagonal));
    addGaps(doc, s.gaps);
    for (const ModelMatrix& m : s.models) {
        doc.subheading(QStringLiteral("Model %1").arg(m.model));
        Table table{QStringLiteral("models-") + m.model, {QStringLiteral("Fitted on")}, {}};
        for (const QString& r : s.runs) table.header << r;
        for (std::size_t i = 0; i < m.matrix.rms_um.size(); ++i) {
            std::vector<Cell> row{text(s.runs[int(i)])};
            for (std::size_t j = 0; j < m.matrix.rms_um[i].size(); ++j) {
                Cell c = number(m.matrix.rms_um[i][j], 2);
                if (i == j) c.text = QStringLiteral("(%1)").arg(c.text);
                row.push_back(c);
            }
            table.rows.push_back(row);
        }
        doc.table(table);
        for (const QString& e : m.matrix.errors) doc.paragraph(QStringLiteral("Failed: ") + e);
    }
}

void addDiagnosis(ReportDocument& doc, const DiagnosisSection& s) {
    if (s.not_applicable.isEmpty()) doc.pageBreak();  // a one-line section shares a page
    doc.heading(QStringLiteral("4 Diagnosis: what the thermal simulation misses"));
    if (!s.not_applicable.isEmpty()) return notApplicable(doc, s.not_applicable);
    const diagnosis::DiagnosisResult& r = s.result;
    doc.paragraph(QStringLiteral("Verdict: %1").arg(r.verdict));
    doc.paragraph(
        QStringLiteral("Base model screw-fdm trained on %1, held out %2: %3 µm RMS, "
                       "peak %4 µm on the held-out runs (reading noise %5 µm).")
            .arg(r.train_runs.join(QStringLiteral(", ")), r.test_runs.join(QStringLiteral(", ")))
            .arg(r.base_test.error_rms_um, 0, 'f', 2)
            .arg(r.base_test.error_peak_um, 0, 'f', 2)
            .arg(r.base_test.error_noise_um, 0, 'f', 2));
    addGaps(doc, r.gaps);
    if (!r.verdict_evidence.isEmpty()) doc.paragraph(r.verdict_evidence);
    if (r.causes.size() > 1)
        doc.paragraph(
            QStringLiteral("Causes found, in order: %1.").arg(r.causes.join(QStringLiteral(", "))));
    // The evidence of each cause in words; the table below has every candidate's figures.
    for (const QString& cause : r.causes)
        if (const auto* f = diagnosis::adoptedFinding(r, cause))
            doc.paragraph(
                QStringLiteral("%1 (step %2): %3").arg(cause).arg(f->step).arg(f->evidence));
    if (!r.remaining.isEmpty()) doc.paragraph(r.remaining);
    Table findings{QStringLiteral("diagnosis-findings"),
                   {QStringLiteral("Cause"), QStringLiteral("Step"), QStringLiteral("Confidence"),
                    QStringLiteral("Significant"), QStringLiteral("Parameters"),
                    QStringLiteral("Quantity"), QStringLiteral("RMS before"),
                    QStringLiteral("RMS after"), QStringLiteral("Held-out gain")},
                   {}};
    for (const diagnosis::Finding& f : r.findings)
        findings.rows.push_back({text(f.cause), number(f.step, 0), number(f.confidence, 2),
                                 text(f.significant ? QStringLiteral("yes") : QStringLiteral("no")),
                                 text(diagnosis::parametersText(f)),
                                 text(f.gain.quantity + QStringLiteral(", ") + f.gain.unit),
                                 number(f.gain.test_rms_before, 3),
                                 number(f.gain.test_rms_after, 3), number(f.gain.reduction, 3)});
    doc.subheading(QStringLiteral("Findings: step 1, then step 2, each by held-out gain"));
    doc.paragraph(
        QStringLiteral(
            "Confidence: the probability that a candidate's held-out gain is real and larger "
            "than every other candidate's of its step, from how the gain varies over stretches "
            "of the held-out runs; for a cause named, times the share of the positioning "
            "structure above the noise that the causes explain%1: what they leave may be a "
            "cause outside the library that a named one imitates. A cause is named only when "
            "it also explains most of the residual.")
            .arg(r.causes.isEmpty()
                     ? QString()
                     : QStringLiteral(" (here %1 %)").arg(100 * r.structure_explained, 0, 'f', 0)));
    doc.table(findings);
    for (std::size_t k = 0; k < r.base_residuals.size(); ++k) {
        const QString run = r.base_residuals[k].run_id;
        const QString title = QStringLiteral("%1: positioning residual of the base model").arg(run);
        doc.plot({QStringLiteral("diagnosis-map-") + run,
                  title,
                  {},
                  {},
                  residualMapPlot(r.base_residuals[k], title),
                  {}});
        if (k >= s.test_runs.size()) continue;
        const auto* adopted = diagnosis::adoptedResiduals(r, k);
        const QString curves = QStringLiteral("%1: verdict %2").arg(run, r.verdict);
        doc.plot({QStringLiteral("diagnosis-before-after-") + run,
                  curves,
                  {},
                  beforeAfterPlot(s.test_runs[k], r.base_residuals[k], adopted,
                                  QStringLiteral("with ") + r.verdict, curves),
                  {},
                  {}});
    }
}

void addCompensation(ReportDocument& doc, const CompensationSection& s) {
    if (s.not_applicable.isEmpty()) doc.pageBreak();  // a one-line section shares a page
    doc.heading(QStringLiteral("5 Pitch-error compensation"));
    if (!s.not_applicable.isEmpty()) return notApplicable(doc, s.not_applicable);
    const compensation::CompensationTable& t = s.table;
    doc.paragraph(QStringLiteral("Table from the ISO 230-2 mean deviations of run %1 (as "
                                 "`driftlab-cli compensate --format csv`): %2 points from %3 to "
                                 "%4 mm, %5. Correction = −deviation, added to the commanded "
                                 "position. After compensation = measured mean deviation + the "
                                 "correction interpolated at the target.")
                      .arg(s.run_id)
                      .arg(t.size())
                      .arg(t.position_mm.front(), 0, 'f', 3)
                      .arg(t.position_mm.back(), 0, 'f', 3)
                      .arg(t.bidirectional ? QStringLiteral("one column per approach")
                                           : QStringLiteral("unidirectional (the mean of both "
                                                            "approaches)")));
    doc.paragraph(QStringLiteral("Peak positioning error: %1 µm before, %2 µm residual after "
                                 "compensation.")
                      .arg(s.before_peak_um, 0, 'f', 3)
                      .arg(s.residual_peak_um, 0, 'f', 3));
    for (const QString& w : s.warnings) doc.paragraph(QStringLiteral("Warning: ") + w);
    CurvePlot plot{QStringLiteral("Run %1: positioning error before and after").arg(s.run_id),
                   QStringLiteral("Target position (mm)"),
                   QStringLiteral("Deviation, actual − target (µm)"),
                   {}};
    const std::pair<QString, double CompensatedTarget::*> series[] = {
        {QStringLiteral("before ↑"), &CompensatedTarget::before_up_um},
        {QStringLiteral("before ↓"), &CompensatedTarget::before_down_um},
        {QStringLiteral("after ↑"), &CompensatedTarget::after_up_um},
        {QStringLiteral("after ↓"), &CompensatedTarget::after_down_um}};
    for (const auto& [name, member] : series) {
        Curve c{name, {}, {}, false};
        for (const CompensatedTarget& p : s.targets)
            if (std::isfinite(p.*member)) c.x.push_back(p.target_mm), c.y.push_back(p.*member);
        if (!c.x.empty()) plot.curves.push_back(c);
    }
    doc.plot({QStringLiteral("compensation-before-after"), plot.title, {}, plot, {}, {}});
    Table before{
        QStringLiteral("compensation-before-after"),
        {QStringLiteral("Target mm"), QStringLiteral("Before ↑ µm"), QStringLiteral("Before ↓ µm"),
         QStringLiteral("After ↑ µm"), QStringLiteral("After ↓ µm")},
        {}};
    for (const CompensatedTarget& p : s.targets)
        before.rows.push_back({number(p.target_mm, 3), number(p.before_up_um, 3),
                               number(p.before_down_um, 3), number(p.after_up_um, 3),
                               number(p.after_down_um, 3)});
    doc.table(before);
    doc.subheading(QStringLiteral("Compensation table"));
    // Each point's expanded uncertainty (95 %, k = 2) beside its corrections,
    // as the CSV export has it.
    const bool uncertain = t.uncertainty_um.size() == t.size();
    Table table{QStringLiteral("compensation-table"),
                {QStringLiteral("position_mm"), QStringLiteral("correction_plus_um"),
                 QStringLiteral("correction_minus_um")},
                {}};
    if (uncertain) table.header << QStringLiteral("uncertainty_um");
    for (std::size_t i = 0; i < t.size(); ++i) {
        std::vector<Cell> row{number(t.position_mm[i], 4), number(t.correction_plus_um[i], 3),
                              number(t.correction_minus_um[i], 3)};
        if (uncertain) row.push_back(number(t.uncertainty_um[i], 3));
        table.rows.push_back(row);
    }
    doc.table(table);
    if (uncertain)
        doc.paragraph(QStringLiteral(
            "uncertainty_um: the expanded uncertainty (95 %, k = 2) of each point's correction, "
            "from the scatter of the cycles the mean deviations are taken over (2·s/√n)."));
}

ReportDocument reportDocument(const AcceptanceReportData& data) {
    ReportDocument doc;
    doc.title = QStringLiteral("DriftLab acceptance report — %1").arg(data.cover.campaign);
    doc.footer = QStringLiteral("%1, axis %2, %3")
                     .arg(data.cover.machine,
                          data.cover.axis.isEmpty() ? QStringLiteral("?") : data.cover.axis,
                          data.cover.report_date);
    addCover(doc, data);
    addIso230_2(doc, data.positioning);
    addIso230_3(doc, data.drift);
    addModels(doc, data.models);
    addDiagnosis(doc, data.diagnosis);
    addCompensation(doc, data.compensation);
    addMachineHistory(doc, data.history);
    return doc;
}

}  // namespace driftlab::ui::report
