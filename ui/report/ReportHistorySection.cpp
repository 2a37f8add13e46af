// Section 6 of the acceptance report: the machine history, every campaign of
// the report's machine and axis in its store (docs/history.md).
#include <cmath>

#include "ui/plots/HistoryPlot.h"
#include "ui/report/ReportDocument.h"

namespace driftlab::ui::report {

void addMachineHistory(ReportDocument& doc, const driftlab::report::HistorySection& s) {
    if (!s.shown()) return;
    const history::MachineHistory& h = *s.history;
    const iso::Settings& iso = h.settings.iso;
    doc.pageBreak();
    doc.heading(QStringLiteral("6 Machine history"));
    doc.paragraph(QStringLiteral("The %1 campaigns of machine %2, axis %3 in the store, oldest "
                                 "first, by the date campaign.json records (the earliest of the "
                                 "campaign's and its runs' dates), else the time the campaign "
                                 "was stored. %4, k = %5, on each campaign's positioning run; "
                                 "drift (ISO 230-3) on its first moving run. * marks this "
                                 "report's campaign.")
                      .arg(h.entries.size())
                      .arg(h.machine, h.axis, iso::toString(iso.edition))
                      .arg(iso.coverage_factor));
    doc.plot({QStringLiteral("machine-history"),
              QStringLiteral("A, E, R, B and M of machine %1, axis %2, against the campaign date")
                  .arg(h.machine, h.axis),
              {},
              historyTrendPlot(h),
              {},
              {}});
    Table table{QStringLiteral("machine-history"),
                {QStringLiteral("Date"), QStringLiteral("Campaign"), QStringLiteral("Run"),
                 QStringLiteral("A µm"), QStringLiteral("E µm"), QStringLiteral("R µm"),
                 QStringLiteral("B µm"), QStringLiteral("M µm"), QStringLiteral("ΔA first"),
                 QStringLiteral("Max drift µm"), QStringLiteral("Stabilised s")},
                {}};
    QStringList notes;
    for (std::size_t i = 0; i < h.entries.size(); ++i) {
        const history::HistoryEntry& e = h.entries[i];
        const QString mark = e.campaign_id == s.campaign_id ? QStringLiteral(" *") : QString();
        std::vector<Cell> row{
            text(e.date.utc.toString(QStringLiteral("yyyy-MM-dd"))),
            text(QStringLiteral("%1 %2%3").arg(e.campaign_id).arg(e.campaign, mark)),
            text(e.positioning.run_id.isEmpty() ? QStringLiteral("—") : e.positioning.run_id)};
        for (history::Figure f : history::kFigures)
            row.push_back(number(e.positioning.value_um(f), 3));
        row.push_back(number(h.changeFromFirst_um(i, history::Figure::A), 3));
        row.push_back(number(e.drift.determined() ? e.drift.max_drift_um : iso::kNotDetermined, 3));
        row.push_back(
            number(e.drift.determined() ? e.drift.stabilised_time_s : iso::kNotDetermined, 0));
        table.rows.push_back(std::move(row));
        if (!e.positioning.not_determined.isEmpty())
            notes << QStringLiteral("Campaign %1: ISO 230-2 not determined: %2.")
                         .arg(e.campaign_id)
                         .arg(e.positioning.not_determined);
        if (!e.positioning.run_note.isEmpty())
            notes << QStringLiteral("Campaign %1: %2.")
                         .arg(e.campaign_id)
                         .arg(e.positioning.run_note);
    }
    doc.table(table);
    doc.paragraph(
        QStringLiteral("ΔA first: A less the first campaign's A. Stabilised s: when the "
                       "drift stabilised (n/a: not within the run, or no moving run)."));
    for (const QString& note : notes) doc.paragraph(note);
}

}  // namespace driftlab::ui::report
