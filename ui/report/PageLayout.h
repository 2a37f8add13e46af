#pragma once
// Page layout of the PDF report: the blocks of a ReportDocument placed on
// pages of a given size, as drawing operations per page (the page count is
// known before the first page is drawn, for "page i of n").

#include <QSizeF>
#include <functional>
#include <vector>

#include "ui/report/ReportDocument.h"

class QCPPainter;
class QPaintDevice;

namespace driftlab::ui::report {

/// Page units: pixels at this resolution (QCustomPlot's pens and fonts are
/// made for a screen; 96 dpi keeps their proportions on paper).
constexpr int kPageDpi = 96;

using PageOp = std::function<void(QCPPainter&)>;
using Pages = std::vector<std::vector<PageOp>>;

/// Places every block of `doc` in the body of pages of `page` size (the
/// header and footer bands left free); `device` measures the text.
Pages layOut(const ReportDocument& doc, QPaintDevice& device, QSizeF page);

/// The header (title) and footer (doc.footer, "page i of n") of one page.
void paintFrame(QCPPainter& painter, const ReportDocument& doc, QSizeF page, int i, int n);

}  // namespace driftlab::ui::report
