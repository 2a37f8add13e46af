#include "ui/report/ReportFolders.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include "ui/report/ReportPlots.h"

namespace driftlab::ui::report {
namespace {

/// What marks a folder as one this writer made (and may replace).
const QString kMarker = QStringLiteral(".driftlab-report");

/// Writes into a temporary folder beside `dir`; publish() renames it into place.
class StagedFolder {
public:
    explicit StagedFolder(const QString& dir)
        : m_dir(QDir::cleanPath(QFileInfo(dir).absoluteFilePath())),
          m_stage(QFileInfo(m_dir).absolutePath() + QStringLiteral("/.report-XXXXXX")) {}

    /// Empty when the folder can be staged; otherwise why not.
    QString check() const {
        const QFileInfo target(m_dir);
        if (target.exists() && !target.isDir())
            return QStringLiteral("%1: exists and is not a folder").arg(m_dir);
        if (target.isDir() && !QDir(m_dir).isEmpty() && !QFile::exists(m_dir + '/' + kMarker))
            return QStringLiteral(
                       "%1: exists and is not a DriftLab report folder; give a new or "
                       "empty folder")
                .arg(m_dir);
        if (!m_stage.isValid())
            return QStringLiteral("%1: cannot write into %2: %3")
                .arg(m_dir, QFileInfo(m_dir).absolutePath(), m_stage.errorString());
        return {};
    }
    QString path(const QString& name) const { return m_stage.filePath(name); }
    bool write(const QString& name, const QByteArray& bytes, QString* error) {
        QFile f(path(name));
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size()) {
            *error = QStringLiteral("%1/%2: cannot write: %3").arg(m_dir, name, f.errorString());
            return false;
        }
        return true;
    }
    bool publish(QString* error) {
        if (!write(kMarker, "DriftLab acceptance report\n", error)) return false;
        const QString old = m_dir + QStringLiteral(".old");
        QDir(old).removeRecursively();
        if (QFileInfo(m_dir).isDir() && !QDir().rename(m_dir, old)) {
            *error = QStringLiteral("%1: cannot replace the older report").arg(m_dir);
            return false;
        }
        if (!QDir().rename(m_stage.path(), m_dir)) {
            QDir().rename(old, m_dir);
            *error = QStringLiteral("%1: cannot move the report into place").arg(m_dir);
            return false;
        }
        m_stage.setAutoRemove(false);
        QDir(old).removeRecursively();
        return true;
    }

private:
    QString m_dir;
    QTemporaryDir m_stage;
};

QString escaped(const QString& text) {
    return text.toHtmlEscaped();
}

QByteArray csvField(const QString& text) {
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) &&
        !text.contains(QLatin1Char('\n')))
        return text.toUtf8();
    QString quoted = text;
    quoted.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return '"' + quoted.toUtf8() + '"';
}

QString htmlTable(const Table& t) {
    QString html = QStringLiteral("<table>\n<tr>");
    for (const QString& h : t.header) html += QStringLiteral("<th>%1</th>").arg(escaped(h));
    html += QStringLiteral("</tr>\n");
    for (const auto& r : t.rows) {
        html += QStringLiteral("<tr>");
        for (const Cell& c : r)
            html += QStringLiteral("<td%1>%2</td>")
                        .arg(c.csv.isEmpty() ? QString() : QStringLiteral(" class=\"n\""),
                             escaped(c.text));
        html += QStringLiteral("</tr>\n");
    }
    return html + QStringLiteral("</table>\n");
}

const char* kStyle =
    "body{font-family:'DejaVu Sans',sans-serif;max-width:60em;margin:2em auto;color:#222}"
    "table{border-collapse:collapse;margin:.5em 0 1em}"
    "th,td{border:1px solid #bbb;padding:2px 6px;font-size:90%}"
    "th{background:#e8ecf2;text-align:left}td.n{text-align:right}"
    "figure{margin:1em 0}img{max-width:100%}figcaption{font-style:italic;color:#555}";

}  // namespace

FolderResult writeReportHtml(const ReportDocument& doc, const QString& dir,
                             const std::function<bool(double)>& progress) {
    FolderResult result;
    StagedFolder folder(dir);
    if (result.error = folder.check(); !result.error.isEmpty()) return result;
    QString html = QStringLiteral(
                       "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>%1</title>"
                       "<style>%2</style></head><body>\n")
                       .arg(escaped(doc.title), QString::fromLatin1(kStyle));
    const std::size_t n = doc.blocks.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (progress && !progress(double(i) / double(n))) {
            result.cancelled = true;
            return result;
        }
        const Block& b = doc.blocks[i];
        switch (b.kind) {
            case Block::Kind::PageBreak:
                break;
            case Block::Kind::Title:
                html += QStringLiteral("<h1>%1</h1>\n").arg(escaped(b.text));
                break;
            case Block::Kind::Heading:
                html += QStringLiteral("<h2>%1</h2>\n").arg(escaped(b.text));
                break;
            case Block::Kind::Subheading:
                html += QStringLiteral("<h3>%1</h3>\n").arg(escaped(b.text));
                break;
            case Block::Kind::Paragraph:
                html += QStringLiteral("<p>%1</p>\n").arg(escaped(b.text));
                break;
            case Block::Kind::Table:
                html += htmlTable(b.table);
                break;
            case Block::Kind::Plot: {
                const QString png = b.plot.id + QStringLiteral(".png");
                if (!plotImage(b.plot, QSize(960, 500)).save(folder.path(png), "PNG")) {
                    result.error = QStringLiteral("%1/%2: cannot write PNG").arg(dir, png);
                    return result;
                }
                result.files << png;
                html += QStringLiteral(
                            "<figure><img src=\"%1\" alt=\"%2\"><figcaption>%2</figcaption>"
                            "</figure>\n")
                            .arg(png, escaped(b.plot.caption));
                break;
            }
        }
    }
    html += QStringLiteral("<footer><p>%1</p></footer>\n</body></html>\n").arg(escaped(doc.footer));
    if (!folder.write(QStringLiteral("index.html"), html.toUtf8(), &result.error)) return result;
    result.files.prepend(QStringLiteral("index.html"));
    if (!folder.publish(&result.error)) result.files.clear();
    return result;
}

FolderResult writeReportCsv(const ReportDocument& doc, const QString& dir) {
    FolderResult result;
    StagedFolder folder(dir);
    if (result.error = folder.check(); !result.error.isEmpty()) return result;
    for (const Table* t : doc.tables()) {
        QByteArray csv;
        QList<QByteArray> fields;
        for (const QString& h : t->header) fields << csvField(h);
        csv += fields.join(',') + "\r\n";
        for (const auto& r : t->rows) {
            fields.clear();
            for (const Cell& c : r) fields << csvField(c.csv.isEmpty() ? c.text : c.csv);
            csv += fields.join(',') + "\r\n";
        }
        const QString name = t->id + QStringLiteral(".csv");
        if (!folder.write(name, csv, &result.error)) return result;
        result.files << name;
    }
    if (!folder.publish(&result.error)) result.files.clear();
    return result;
}

}  // namespace driftlab::ui::report
