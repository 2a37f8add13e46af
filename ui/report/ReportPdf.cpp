#include "ui/report/ReportPdf.h"

#include <qcustomplot.h>

#include <QPdfWriter>
#include <QSaveFile>

#include "ui/report/PageLayout.h"

namespace driftlab::ui::report {

PdfResult writeReportPdf(const ReportDocument& doc, const QString& path,
                         const std::function<bool(double)>& progress) {
    PdfResult result;
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        result.error = QStringLiteral("%1: cannot write: %2").arg(path, file.errorString());
        return result;
    }
    QPdfWriter writer(&file);
    writer.setPageSize(QPageSize(QPageSize::A4));
    writer.setPageMargins(QMarginsF(16, 12, 16, 12), QPageLayout::Millimeter);
    writer.setResolution(kPageDpi);
    writer.setTitle(doc.title);
    writer.setCreator(QStringLiteral("DriftLab"));
    const QRect area = writer.pageLayout().paintRectPixels(kPageDpi);
    const Pages pages = layOut(doc, writer, QSizeF(area.width(), area.height()));

    QCPPainter painter;
    if (!painter.begin(&writer)) {
        result.error = QStringLiteral("%1: cannot start the PDF").arg(path);
        return result;
    }
    painter.setMode(QCPPainter::pmVectorized);
    const int n = int(pages.size());
    for (int i = 0; i < n; ++i) {
        if (progress && !progress(double(i) / n)) {
            painter.end();
            file.cancelWriting();
            result.cancelled = true;
            return result;
        }
        if (i > 0) writer.newPage();
        paintFrame(painter, doc, QSizeF(area.width(), area.height()), i + 1, n);
        for (const PageOp& op : pages[std::size_t(i)]) op(painter);
    }
    painter.end();
    if (!file.commit()) {
        result.error = QStringLiteral("%1: cannot write: %2").arg(path, file.errorString());
        return result;
    }
    if (progress) progress(1);
    result.pages = n;
    return result;
}

}  // namespace driftlab::ui::report
