#pragma once
// The acceptance report as a PDF: A4 pages with a header and a "page i of
// n" footer, tables that break across pages (their header repeated), plots
// drawn as vectors through QCustomPlot::toPainter. Written through QSaveFile:
// a failed or cancelled export leaves no file (and an older one untouched).

#include <QString>
#include <functional>
#include <memory>

#include "ui/report/ReportDocument.h"

namespace driftlab::ui::report {

struct PdfResult {
    QString error;  ///< empty on success; names the path and why
    bool cancelled = false;
    int pages = 0;
    bool ok() const { return error.isEmpty() && !cancelled; }
};

/// A PDF drawn one page at a time, so that the GUI can draw a page per turn
/// of its event loop (and take a Cancel between pages). GUI thread only:
/// plots are widgets.
class PdfRendering {
public:
    /// Opens `path` (through QSaveFile) and lays `doc` out; see error().
    PdfRendering(ReportDocument doc, const QString& path);
    ~PdfRendering();  ///< unfinished: nothing is written

    QString error() const { return m_error; }
    int pageCount() const;
    int pagesDrawn() const { return m_next; }
    /// Draws the next page; false when there is none left (or an error).
    bool drawNextPage();
    /// Ends the PDF and moves it into place (every page drawn first).
    PdfResult finish();

private:
    struct State;
    ReportDocument m_doc;
    QString m_path, m_error;
    std::unique_ptr<State> m_state;
    int m_next = 0;
};

/// Lays out and writes `doc` to `path` in one go. `progress` gets the
/// fraction of pages drawn and may return false to cancel.
PdfResult writeReportPdf(const ReportDocument& doc, const QString& path,
                         const std::function<bool(double)>& progress = {});

}  // namespace driftlab::ui::report
