#pragma once
// The acceptance report as a sequence of blocks (headings, paragraphs,
// tables, plots), built once from the report data and written by each
// renderer: PDF (ReportPdf), HTML (ReportHtml) and CSV (ReportCsv, the
// tables only). The renderers lay out and draw; they never decide content.

#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "core/iso/Iso230_2.h"
#include "core/report/AcceptanceReportData.h"
#include "ui/plots/PngPlots.h"

namespace driftlab::ui::report {

/// One table cell: the text printed, and the value at full precision for CSV.
struct Cell {
    QString text;
    QString csv;  ///< empty: the text
};

/// `value` with `decimals` in print, round-trip precision in CSV; NaN is "n/a".
Cell number(double value, int decimals);
Cell text(const QString& value);

struct Table {
    QString id;  ///< the CSV file stem, e.g. "iso230-2-axis"
    QStringList header;
    std::vector<std::vector<Cell>> rows;
};

/// A figure: exactly one of the three descriptions is set.
struct Plot {
    QString id;  ///< the PNG file stem of the HTML report
    QString caption;
    std::optional<iso::Evaluation> iso230_2;  ///< drawn by the GUI's Iso230_2Plot
    std::optional<CurvePlot> curves;
    std::optional<MapPlot> map;
    std::optional<double> accuracy_tolerance_um;  ///< tolerance lines on the ISO 230-2 plot
};

struct Block {
    enum class Kind { Title, Heading, Subheading, Paragraph, Table, Plot, PageBreak };
    Kind kind = Kind::Paragraph;
    QString text;
    Table table;
    Plot plot;
};

struct ReportDocument {
    QString title;   ///< the page header
    QString footer;  ///< left of "page i of n"
    std::vector<Block> blocks;

    void pageBreak() { blocks.push_back({Block::Kind::PageBreak, {}, {}, {}}); }
    void titleBlock(const QString& t) { blocks.push_back({Block::Kind::Title, t, {}, {}}); }
    void heading(const QString& t) { blocks.push_back({Block::Kind::Heading, t, {}, {}}); }
    void subheading(const QString& t) { blocks.push_back({Block::Kind::Subheading, t, {}, {}}); }
    void paragraph(const QString& t) { blocks.push_back({Block::Kind::Paragraph, t, {}, {}}); }
    void table(Table t) { blocks.push_back({Block::Kind::Table, {}, std::move(t), {}}); }
    void plot(Plot p) { blocks.push_back({Block::Kind::Plot, {}, {}, std::move(p)}); }
    std::vector<const Table*> tables() const;
};

/// The whole report, sections 1-6 in order, and the machine history where there is one
/// (docs/report.md).
ReportDocument reportDocument(const driftlab::report::AcceptanceReportData& data);

// The sections, one builder each (ReportIsoSections.cpp, ReportModelSections.cpp).
void addCover(ReportDocument& doc, const driftlab::report::AcceptanceReportData& data);
void addIso230_2(ReportDocument& doc, const driftlab::report::PositioningSection& s);
void addIso230_3(ReportDocument& doc, const driftlab::report::DriftSection& s);
void addModels(ReportDocument& doc, const driftlab::report::ModelSection& s);
void addDiagnosis(ReportDocument& doc, const driftlab::report::DiagnosisSection& s);
void addCompensation(ReportDocument& doc, const driftlab::report::CompensationSection& s);
/// Only when the store holds more than one campaign of the machine and axis
/// (ReportHistorySection.cpp).
void addMachineHistory(ReportDocument& doc, const driftlab::report::HistorySection& s);

}  // namespace driftlab::ui::report
