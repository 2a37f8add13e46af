#include "ui/report/PageLayout.h"

#include <qcustomplot.h>

#include <QFontMetricsF>
#include <algorithm>

#include "ui/report/ReportPlots.h"

namespace driftlab::ui::report {
namespace {

constexpr double kFrame = 26;     ///< header and footer bands
constexpr double kGap = 8;        ///< between blocks
constexpr double kPad = 3;        ///< inside table cells
constexpr double kKeepWith = 90;  ///< a heading needs this much below it on its page

QFont font(int points, bool bold = false, bool italic = false) {
    QFont f(QStringLiteral("DejaVu Sans"), points, bold ? QFont::Bold : QFont::Normal, italic);
    f.setStyleHint(QFont::SansSerif);
    return f;
}

/// Places blocks top to bottom, starting a page where the next one does not fit.
class Placer {
public:
    Placer(QPaintDevice& device, QSizeF page) : m_device(device), m_page(page) { newPage(); }

    Pages take() {
        if (m_pages.back().empty()) m_pages.pop_back();
        return std::move(m_pages);
    }
    double width() const { return m_page.width(); }
    double left() const { return m_page.height() - kFrame - m_y; }
    bool pageEmpty() const { return m_pages.back().empty(); }
    void newPage() {
        m_pages.emplace_back();
        m_y = kFrame;
    }
    /// Room for `height` on this page, or a new page.
    void need(double height) {
        if (height > left() && !pageEmpty()) newPage();
    }
    double textHeight(const QFont& f, const QString& text, double width) const {
        return QFontMetricsF(f, &m_device)
            .boundingRect(QRectF(0, 0, width, 1e6), Qt::TextWordWrap, text)
            .height();
    }
    double textWidth(const QFont& f, const QString& text) const {
        double w = 0;
        for (const QString& line : text.split(QLatin1Char('\n')))
            w = std::max(w, QFontMetricsF(f, &m_device).horizontalAdvance(line));
        return w;
    }

    void text(const QFont& f, const QString& text, double spaceBefore, double keepWith = 0) {
        const double h = textHeight(f, text, width());
        need(h + spaceBefore + keepWith);
        if (!pageEmpty()) m_y += spaceBefore;
        const QRectF r(0, m_y, width(), h);
        add([f, r, text](QCPPainter& p) {
            p.setFont(f);
            p.setPen(Qt::black);
            p.drawText(r, Qt::TextWordWrap, text);
        });
        m_y += h + kGap / 2;
    }

    void plot(const Plot& plot) {
        const double w = width(), h = std::round(w * 0.52);
        const QFont captionFont = font(8, false, true);
        const double ch = textHeight(captionFont, plot.caption, w);
        need(h + ch + kGap);
        const double y = m_y;
        add([plot, w, h, y](QCPPainter& p) {
            p.save();
            p.translate(0, y);
            p.setClipRect(QRectF(0, 0, w, h));
            paintPlot(plot, p, QSize(int(w), int(h)));
            p.restore();
        });
        m_y += h + 2;
        const QRectF r(0, m_y, w, ch);
        add([captionFont, r, caption = plot.caption](QCPPainter& p) {
            p.setFont(captionFont);
            p.setPen(Qt::darkGray);
            p.drawText(r, Qt::TextWordWrap | Qt::AlignHCenter, caption);
        });
        m_y += ch + kGap;
    }

    void table(const Table& t);
    /// The height of the whole table when it fits on one page, else 0: a
    /// table that fits is not split, and its heading stays with all of it.
    double wholeTableHeight(const Table& t) const;

private:
    void add(PageOp op) { m_pages.back().push_back(std::move(op)); }
    /// Column widths: natural when they fit, else the wide columns share what
    /// the narrow ones leave, and their text wraps.
    std::vector<double> columnWidths(const Table& t, const QFont& body, const QFont& head) const;
    double rowHeight(const std::vector<QString>& cells, const std::vector<double>& widths,
                     const QFont& f) const;
    void row(const std::vector<QString>& cells, const std::vector<bool>& right,
             const std::vector<double>& widths, double height, const QFont& f, bool header);

    QPaintDevice& m_device;
    QSizeF m_page;
    Pages m_pages;
    double m_y = 0;
};

std::vector<double> Placer::columnWidths(const Table& t, const QFont& body,
                                         const QFont& head) const {
    std::vector<double> natural(std::size_t(t.header.size()), 0);
    for (const auto& r : t.rows)
        for (std::size_t c = 0; c < r.size() && c < natural.size(); ++c)
            natural[c] = std::max(natural[c], textWidth(body, r[c].text) + 2 * kPad + 1);
    std::vector<double> cells = natural;
    double total = 0;
    for (int c = 0; c < t.header.size(); ++c) {
        natural[std::size_t(c)] =
            std::max(natural[std::size_t(c)], textWidth(head, t.header[c]) + 2 * kPad + 1);
        total += natural[std::size_t(c)];
    }
    if (total <= width()) return natural;
    // Too wide: a header wraps at its blanks, its longest word is what it needs.
    natural = cells;
    for (int c = 0; c < t.header.size(); ++c)
        for (const QString& word : t.header[c].split(QLatin1Char(' ')))
            natural[std::size_t(c)] =
                std::max(natural[std::size_t(c)], textWidth(head, word) + 2 * kPad + 1);
    // Water-filling: a column narrower than an equal share of what is left
    // keeps its width (identifiers do not wrap); the widest share the rest.
    std::vector<double> widths = natural;
    std::vector<bool> open(natural.size(), true);
    double remaining = width();
    std::size_t openCount = natural.size();
    for (bool fixed = true; fixed && openCount > 0;) {
        fixed = false;
        const double share = remaining / double(openCount);
        for (std::size_t c = 0; c < natural.size(); ++c)
            if (open[c] && natural[c] <= share) {
                open[c] = false;
                remaining -= natural[c];
                --openCount;
                fixed = true;
            }
    }
    for (std::size_t c = 0; c < natural.size(); ++c)
        if (open[c]) widths[c] = remaining / double(openCount);
    return widths;
}

double Placer::rowHeight(const std::vector<QString>& cells, const std::vector<double>& widths,
                         const QFont& f) const {
    double h = 0;
    for (std::size_t c = 0; c < cells.size() && c < widths.size(); ++c)
        h = std::max(h, textHeight(f, cells[c], widths[c] - 2 * kPad));
    return h + 2 * kPad;
}

void Placer::row(const std::vector<QString>& cells, const std::vector<bool>& right,
                 const std::vector<double>& widths, double height, const QFont& f, bool header) {
    const double y = m_y;
    add([=](QCPPainter& p) {
        double x = 0;
        p.setFont(f);
        for (std::size_t c = 0; c < widths.size(); ++c) {
            const QRectF cell(x, y, widths[c], height);
            if (header) p.fillRect(cell, QColor(0xe8, 0xec, 0xf2));
            p.setPen(QPen(QColor(0xb0, 0xb0, 0xb0), 0.5));
            p.drawRect(cell);
            p.setPen(Qt::black);
            const int align = Qt::TextWordWrap | Qt::AlignVCenter |
                              (right[c] && !header ? Qt::AlignRight : Qt::AlignLeft);
            if (c < cells.size())
                p.drawText(cell.adjusted(kPad, kPad, -kPad, -kPad), align, cells[c]);
            x += widths[c];
        }
    });
    m_y += height;
}

double Placer::wholeTableHeight(const Table& t) const {
    const QFont body = font(7), head = font(7, true);
    const std::vector<double> widths = columnWidths(t, body, head);
    double h = rowHeight(std::vector<QString>(t.header.begin(), t.header.end()), widths, head);
    for (const auto& r : t.rows) {
        std::vector<QString> cells;
        for (const Cell& c : r) cells.push_back(c.text);
        h += rowHeight(cells, widths, body);
    }
    return h <= m_page.height() - 2 * kFrame ? h : 0;
}

void Placer::table(const Table& t) {
    need(wholeTableHeight(t));
    const QFont body = font(7), head = font(7, true);
    const std::vector<double> widths = columnWidths(t, body, head);
    const std::vector<QString> header(t.header.begin(), t.header.end());
    const double headerHeight = rowHeight(header, widths, head);
    std::vector<bool> right(widths.size(), false);
    for (const auto& r : t.rows)
        for (std::size_t c = 0; c < r.size() && c < right.size(); ++c)
            if (!r[c].csv.isEmpty()) right[c] = true;
    bool first = true;
    for (const auto& r : t.rows) {
        std::vector<QString> cells;
        for (const Cell& c : r) cells.push_back(c.text);
        const double h = rowHeight(cells, widths, body);
        if (first || h > left()) {
            // A table starts, or goes on, under its header.
            if (!first) newPage();
            need(headerHeight + h);
            row(header, right, widths, headerHeight, head, true);
            first = false;
        }
        row(cells, right, widths, h, body, false);
    }
    if (first) row(header, right, widths, headerHeight, head, true);
    m_y += kGap;
}

}  // namespace

Pages layOut(const ReportDocument& doc, QPaintDevice& device, QSizeF page) {
    Placer placer(device, page);
    for (std::size_t i = 0; i < doc.blocks.size(); ++i) {
        const Block& b = doc.blocks[i];
        // A heading keeps room below it for the table it introduces, when that fits.
        const bool tableNext =
            i + 1 < doc.blocks.size() && doc.blocks[i + 1].kind == Block::Kind::Table;
        const double keepWith =
            std::max(kKeepWith, tableNext ? placer.wholeTableHeight(doc.blocks[i + 1].table) : 0);
        switch (b.kind) {
            case Block::Kind::PageBreak:
                if (!placer.pageEmpty()) placer.newPage();
                break;
            case Block::Kind::Title:
                placer.text(font(22, true), b.text, 40);
                break;
            case Block::Kind::Heading:
                placer.text(font(14, true), b.text, 4, keepWith);
                break;
            case Block::Kind::Subheading:
                placer.text(font(10, true), b.text, 8, keepWith);
                break;
            case Block::Kind::Paragraph:
                placer.text(font(9), b.text, 0);
                break;
            case Block::Kind::Table:
                placer.table(b.table);
                break;
            case Block::Kind::Plot:
                placer.plot(b.plot);
                break;
        }
    }
    return placer.take();
}

void paintFrame(QCPPainter& painter, const ReportDocument& doc, QSizeF page, int i, int n) {
    painter.setFont(font(7));
    painter.setPen(Qt::darkGray);
    const double w = page.width(), h = page.height();
    painter.drawText(QRectF(0, 0, w, kFrame - 10), Qt::AlignLeft | Qt::AlignBottom, doc.title);
    painter.drawLine(QPointF(0, kFrame - 6), QPointF(w, kFrame - 6));
    painter.drawLine(QPointF(0, h - kFrame + 6), QPointF(w, h - kFrame + 6));
    const QRectF foot(0, h - kFrame + 10, w, kFrame - 10);
    painter.drawText(foot, Qt::AlignLeft | Qt::AlignTop, doc.footer);
    painter.drawText(foot, Qt::AlignRight | Qt::AlignTop,
                     QStringLiteral("page %1 of %2").arg(i).arg(n));
}

}  // namespace driftlab::ui::report
