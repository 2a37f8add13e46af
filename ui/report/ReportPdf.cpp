#include "ui/report/ReportPdf.h"

#include <qcustomplot.h>

#include <QPdfWriter>
#include <QSaveFile>

#include "ui/report/PageLayout.h"

namespace driftlab::ui::report {

struct PdfRendering::State {
    explicit State(const QString& path) : file(path) {}
    QSaveFile file;
    std::unique_ptr<QPdfWriter> writer;
    QCPPainter painter;
    QSizeF area;
    Pages pages;
};

PdfRendering::PdfRendering(ReportDocument doc, const QString& path)
    : m_doc(std::move(doc)), m_path(path), m_state(std::make_unique<State>(path)) {
    State& s = *m_state;
    if (!s.file.open(QIODevice::WriteOnly)) {
        m_error = QStringLiteral("%1: cannot write: %2").arg(path, s.file.errorString());
        return;
    }
    s.writer = std::make_unique<QPdfWriter>(&s.file);
    s.writer->setPageSize(QPageSize(QPageSize::A4));
    s.writer->setPageMargins(QMarginsF(16, 12, 16, 12), QPageLayout::Millimeter);
    s.writer->setResolution(kPageDpi);
    s.writer->setTitle(m_doc.title);
    s.writer->setCreator(QStringLiteral("DriftLab"));
    const QRect area = s.writer->pageLayout().paintRectPixels(kPageDpi);
    s.area = QSizeF(area.width(), area.height());
    s.pages = layOut(m_doc, *s.writer, s.area);
    if (!s.painter.begin(s.writer.get())) {
        m_error = QStringLiteral("%1: cannot start the PDF").arg(path);
        return;
    }
    s.painter.setMode(QCPPainter::pmVectorized);
}

PdfRendering::~PdfRendering() {
    if (m_state->painter.isActive()) m_state->painter.end();
    m_state->file.cancelWriting();  // after commit(), a no-op
}

int PdfRendering::pageCount() const {
    return int(m_state->pages.size());
}

bool PdfRendering::drawNextPage() {
    if (!m_error.isEmpty() || m_next >= pageCount()) return false;
    State& s = *m_state;
    if (m_next > 0) s.writer->newPage();
    paintFrame(s.painter, m_doc, s.area, m_next + 1, pageCount());
    for (const PageOp& op : s.pages[std::size_t(m_next)]) op(s.painter);
    ++m_next;
    return true;
}

PdfResult PdfRendering::finish() {
    PdfResult result;
    while (drawNextPage()) {
    }
    result.error = m_error;
    if (!result.ok()) return result;
    m_state->painter.end();
    if (!m_state->file.commit()) {
        result.error =
            QStringLiteral("%1: cannot write: %2").arg(m_path, m_state->file.errorString());
        return result;
    }
    result.pages = pageCount();
    return result;
}

PdfResult writeReportPdf(const ReportDocument& doc, const QString& path,
                         const std::function<bool(double)>& progress) {
    PdfRendering pdf(doc, path);
    if (!pdf.error().isEmpty()) return {pdf.error(), false, 0};
    do {
        if (progress && !progress(double(pdf.pagesDrawn()) / pdf.pageCount()))
            return {{}, true, 0};  // the rendering's destructor discards the file
    } while (pdf.drawNextPage());
    const PdfResult result = pdf.finish();
    if (result.ok() && progress) progress(1);
    return result;
}

}  // namespace driftlab::ui::report
