#pragma once
// File → Export report…: the acceptance report of the selected campaign as a
// PDF. The analysis (cross-state matrix, diagnosis: the minutes) runs on a
// worker thread (BackgroundJob) under a QProgressDialog with Cancel; the
// pages are then drawn on the GUI thread, because QCustomPlot is a widget
// and widgets belong to the GUI thread: one page per turn of the event loop
// (tens of ms each), so the window stays live and Cancel works between pages.
// The PDF goes through QSaveFile: a cancelled or failed export leaves no file.

#include <QObject>
#include <QString>
#include <memory>

#include "core/report/AcceptanceReportData.h"

class QProgressDialog;
class QWidget;

namespace driftlab::ui {
namespace report {
class PdfRendering;
}

class BackgroundJob;
class Session;

class ReportExport : public QObject {
    Q_OBJECT
public:
    ReportExport(Session& session, QWidget* dialogParent);
    ~ReportExport() override;

    /// The analysis or the drawing is under way.
    bool isRunning() const;
    QProgressDialog* progressDialog() const { return m_dialog; }

public slots:
    /// Exports the selected campaign's report to `pdfPath`; false (and
    /// finished() is not emitted) when no campaign is selected or an export runs.
    bool start(const QString& pdfPath);
    void cancel();

signals:
    /// `written`: the PDF is there; otherwise `message` says why not (or "cancelled").
    void finished(bool written, const QString& message);

private:
    void render(const driftlab::report::AcceptanceReportData& data);
    void drawNextPage();
    void finish(bool written, const QString& message);

    Session& m_session;
    BackgroundJob* m_job;
    std::unique_ptr<report::PdfRendering> m_pdf;  ///< while the pages are drawn
    QProgressDialog* m_dialog;
    QString m_path;
    bool m_cancelled = false;
};

}  // namespace driftlab::ui
