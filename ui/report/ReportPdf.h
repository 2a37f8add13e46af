#pragma once
// The acceptance report as a PDF: A4 pages with a header and a "page i of
// n" footer, tables that break across pages (their header repeated), plots
// drawn as vectors through QCustomPlot::toPainter. Written through QSaveFile:
// a failed or cancelled export leaves no file (and an older one untouched).

#include <QString>
#include <functional>

#include "ui/report/ReportDocument.h"

namespace driftlab::ui::report {

struct PdfResult {
    QString error;  ///< empty on success; names the path and why
    bool cancelled = false;
    int pages = 0;
    bool ok() const { return error.isEmpty() && !cancelled; }
};

/// Lays out and writes `doc` to `path`. `progress` gets the fraction of pages
/// drawn and may return false to cancel. GUI thread only (plots are widgets).
PdfResult writeReportPdf(const ReportDocument& doc, const QString& path,
                         const std::function<bool(double)>& progress = {});

}  // namespace driftlab::ui::report
