// bench: the acceptance report of the five-state campaign of `simulate
// --seed 1`: building its data (cross-state matrix of every model and the
// diagnosis: report_data_ms) and drawing the PDF (report_render_ms), medians.
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <algorithm>
#include <vector>

#include "bench/BenchFigures.h"
#include "core/report/AcceptanceReportData.h"
#include "core/rig/CampaignSimulator.h"
#include "ui/report/ReportPdf.h"

namespace driftlab::bench {
QJsonObject reportFigures(int repetitions) {
    const Campaign campaign = rig::simulateCampaign(rig::RigSpec{});
    report::ReportOptions options;
    options.version = QStringLiteral(DRIFTLAB_VERSION);
    options.report_date = QStringLiteral("bench");
    std::vector<double> dataMs, renderMs;
    report::AcceptanceReportData data;
    const double steps = 2.0 * repetitions;
    for (int i = 0; i < repetitions; ++i) {
        options.progress = [i, steps](double f) {
            return printProgress(QStringLiteral("report"), (i + f) / steps);
        };
        QElapsedTimer timer;
        timer.start();
        data = report::buildReportData(campaign, options);
        dataMs.push_back(timer.nsecsElapsed() * 1e-6);
        if (!data.ok()) throw CliError(QStringLiteral("report data: ") + data.error);
    }
    QTemporaryDir dir;
    int pages = 0;
    for (int i = 0; i < repetitions; ++i) {
        QElapsedTimer timer;
        timer.start();
        const ui::report::PdfResult r = ui::report::writeReportPdf(
            ui::report::reportDocument(data), dir.filePath(QStringLiteral("report.pdf")));
        renderMs.push_back(timer.nsecsElapsed() * 1e-6);
        if (!r.ok()) throw CliError(r.error);
        pages = r.pages;
        printProgress(QStringLiteral("report"), (repetitions + i + 1.0) / steps);
    }
    return {{QStringLiteral("report_data_ms"), median(dataMs)},
            {QStringLiteral("report_render_ms"), median(renderMs)},
            {QStringLiteral("report_pages"), pages}};
}

void printReportLine(const QJsonObject& figures) {
    printLine(QStringLiteral("report          5-run campaign, %1 pages: data (compare + "
                             "diagnosis) %2 ms, PDF drawing %3 ms (medians)")
                  .arg(figures[QStringLiteral("report_pages")].toInt())
                  .arg(figures[QStringLiteral("report_data_ms")].toDouble(), 0, 'f', 0)
                  .arg(figures[QStringLiteral("report_render_ms")].toDouble(), 0, 'f', 0));
}

}  // namespace driftlab::bench
