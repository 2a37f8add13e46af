#pragma once
// The HTML report (a folder: index.html + one PNG per plot) and the CSV
// report (a folder: one CSV per table). A folder is written beside its
// destination and renamed into place at the end: a failed or cancelled
// export leaves no folder, and an older report is replaced only when the
// new one is complete. A folder that is not a DriftLab report is never
// replaced.

#include <QStringList>
#include <functional>

#include "ui/report/ReportDocument.h"

namespace driftlab::ui::report {

struct FolderResult {
    QString error;  ///< empty on success; names the path and why
    bool cancelled = false;
    QStringList files;  ///< written, relative to the folder
    bool ok() const { return error.isEmpty() && !cancelled; }
};

/// index.html and the plots as PNG. GUI thread only (plots are widgets).
FolderResult writeReportHtml(const ReportDocument& doc, const QString& dir,
                             const std::function<bool(double)>& progress = {});
/// One RFC 4180 CSV per table (`Table::id`.csv), numbers at full precision.
FolderResult writeReportCsv(const ReportDocument& doc, const QString& dir);

}  // namespace driftlab::ui::report
