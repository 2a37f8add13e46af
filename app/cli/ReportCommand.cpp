// report: the acceptance report of a campaign as PDF, HTML and/or CSV
// (docs/report.md). The data comes from core/report,
// the pages from ui/report; this file only wires options to them.
#include <QDateTime>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>

#include "app/cli/CliCommon.h"
#include "app/cli/FlaggedSamples.h"
#include "app/cli/IsoOptions.h"
#include "core/report/AcceptanceReportData.h"
#include "db/MachineHistoryStore.h"
#include "ui/report/ReportFolders.h"
#include "ui/report/ReportPdf.h"

namespace driftlab::cli {
namespace {

/// Refuses, before any work, an output whose folder does not exist or cannot be written.
void checkWritable(const QString& option, const QString& path) {
    const QFileInfo parent(QFileInfo(path).absolutePath());
    if (!parent.exists())
        throw CliError(QStringLiteral("--%1 %2: folder %3 does not exist")
                           .arg(option, path, parent.filePath()));
    if (!parent.isDir())
        throw CliError(
            QStringLiteral("--%1 %2: %3 is not a folder").arg(option, path, parent.filePath()));
    if (!parent.isWritable())
        throw CliError(QStringLiteral("--%1 %2: folder %3 is not writable")
                           .arg(option, path, parent.filePath()));
    if (QFileInfo(path).isDir() && option == QLatin1String("pdf"))
        throw CliError(QStringLiteral("--pdf %1: is a folder").arg(path));
}

QJsonObject keyFigures(const report::AcceptanceReportData& data) {
    QJsonObject json{{QStringLiteral("campaign"), data.cover.campaign}};
    const report::PositioningSection& p = data.positioning;
    if (p.not_applicable.isEmpty()) {
        const iso::AxisResult& a = p.evaluation.axis;
        json[QStringLiteral("iso230_2")] =
            QJsonObject{{QStringLiteral("run"), p.run_id},
                        {QStringLiteral("B"), jsonNumber(a.reversal_um)},
                        {QStringLiteral("R"), jsonNumber(a.r_um)},
                        {QStringLiteral("E"), jsonNumber(a.e_um)},
                        {QStringLiteral("M"), jsonNumber(a.m_um)},
                        {QStringLiteral("A"), jsonNumber(a.a_um)}};
    }
    if (data.diagnosis.not_applicable.isEmpty())
        json[QStringLiteral("verdict")] = data.diagnosis.result.verdict;
    if (data.compensation.not_applicable.isEmpty())
        json[QStringLiteral("compensation")] =
            QJsonObject{{QStringLiteral("run"), data.compensation.run_id},
                        {QStringLiteral("before_peak_um"), data.compensation.before_peak_um},
                        {QStringLiteral("residual_peak_um"), data.compensation.residual_peak_um}};
    QJsonObject notApplicable;
    const std::pair<const char*, QString> sections[] = {
        {"iso230_2", p.not_applicable},
        {"iso230_3", data.drift.not_applicable},
        {"models", data.models.not_applicable},
        {"diagnosis", data.diagnosis.not_applicable},
        {"compensation", data.compensation.not_applicable}};
    for (const auto& [name, why] : sections)
        if (!why.isEmpty()) notApplicable[QString::fromLatin1(name)] = why;
    json[QStringLiteral("not_applicable")] = notApplicable;
    return json;
}

/// The other campaigns of the machine axis in the store, for the report's
/// machine history; a store that cannot give it costs the section, not the report.
void addMachineHistory(const QCommandLineParser& parser, const Campaign& campaign,
                       report::AcceptanceReportData& data) {
    auto store = openSourceStore(parser, db::StoreAccess::ReadOnly);
    history::HistorySettings settings{data.positioning.evaluation.settings, {}};
    QString error;
    data.history.history =
        db::machineHistory(*store, campaign.machine.name, campaign.machine.axis, settings, &error);
    data.history.campaign_id = parser.value(QStringLiteral("campaign")).toLongLong();
    if (!data.history.history) printWarnings({QStringLiteral("no machine history: ") + error});
}

}  // namespace

int reportCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption pdf{QStringLiteral("pdf"),
                                 QStringLiteral("Write the report as a PDF file."),
                                 QStringLiteral("FILE")};
    const QCommandLineOption html{
        QStringLiteral("html"),
        QStringLiteral("Write the report as HTML: a folder with index.html and the plots as PNG."),
        QStringLiteral("DIR")};
    const QCommandLineOption csv{
        QStringLiteral("csv"),
        QStringLiteral("Write the report's tables as CSV: a folder with one file per table."),
        QStringLiteral("DIR")};
    const QCommandLineOption runOption{
        QStringLiteral("run"),
        QStringLiteral("The run of the ISO 230-2 section and the compensation table (default: "
                       "the positioning run, else the only run with readings, else the first)."),
        QStringLiteral("R")};
    const QCommandLineOption operatorOption{
        QStringLiteral("operator"),
        QStringLiteral("Who ran the test, for the cover (default: \"not given\")."),
        QStringLiteral("NAME")};
    Arguments arguments = campaignSourceArguments();
    parseArguments(parser, args,
                   campaignSourceOptions() << pdf << html << csv << runOption << operatorOption
                                           << keepFlaggedOption() << acceptanceSpecOption(),
                   arguments);
    if (!parser.isSet(pdf) && !parser.isSet(html) && !parser.isSet(csv))
        throw CliError(QStringLiteral("give at least one of --pdf FILE, --html DIR, --csv DIR"), 2);
    // Outputs are checked before the minutes of work, not after.
    for (const QCommandLineOption* o : {&pdf, &html, &csv})
        if (parser.isSet(*o)) checkWritable(o->names().front(), parser.value(*o));

    Campaign campaign = loadCampaignSource(parser);
    leaveOutFlaggedSamples(parser, campaign);
    const QString run = parser.value(runOption);
    if (!run.isEmpty() && !campaign.findRun(run))
        throw CliError(QStringLiteral("--run: no run '%1' in campaign %2").arg(run, campaign.name),
                       2);

    report::ReportOptions options;
    options.positioning_run = run;
    options.operator_name = parser.value(operatorOption);
    options.acceptance = acceptanceSpecification(parser, campaign);
    options.version = QStringLiteral(DRIFTLAB_VERSION);
    options.report_date =
        QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyy-MM-dd HH:mm 'UTC'"));
    options.progress = [](double f) { return printProgress(QStringLiteral("analysing"), f); };
    QElapsedTimer timer;
    timer.start();
    report::AcceptanceReportData data = report::buildReportData(campaign, options);
    endProgressLine();
    if (!data.error.isEmpty()) throw CliError(data.error);
    if (parser.isSet(QStringLiteral("db"))) addMachineHistory(parser, campaign, data);
    const double dataMs = timer.nsecsElapsed() * 1e-6;

    timer.restart();
    const ui::report::ReportDocument doc = ui::report::reportDocument(data);
    QJsonObject written;
    if (parser.isSet(pdf)) {
        const ui::report::PdfResult r = ui::report::writeReportPdf(
            doc, parser.value(pdf),
            [](double f) { return printProgress(QStringLiteral("writing PDF"), f); });
        endProgressLine();
        if (!r.ok()) throw CliError(r.error);
        written[QStringLiteral("pdf")] = parser.value(pdf);
        written[QStringLiteral("pages")] = r.pages;
    }
    if (parser.isSet(html)) {
        const ui::report::FolderResult r = ui::report::writeReportHtml(
            doc, parser.value(html),
            [](double f) { return printProgress(QStringLiteral("writing HTML"), f); });
        endProgressLine();
        if (!r.ok()) throw CliError(r.error);
        written[QStringLiteral("html")] = parser.value(html);
        written[QStringLiteral("html_files")] = QJsonArray::fromStringList(r.files);
    }
    if (parser.isSet(csv)) {
        const ui::report::FolderResult r = ui::report::writeReportCsv(doc, parser.value(csv));
        if (!r.ok()) throw CliError(r.error);
        written[QStringLiteral("csv")] = parser.value(csv);
        written[QStringLiteral("csv_files")] = QJsonArray::fromStringList(r.files);
    }
    const double renderMs = timer.nsecsElapsed() * 1e-6;

    if (parser.isSet(QStringLiteral("json"))) {
        QJsonObject json = keyFigures(data);
        json[QStringLiteral("written")] = written;
        json[QStringLiteral("data_ms")] = dataMs;
        json[QStringLiteral("render_ms")] = renderMs;
        printJson(json);
        return 0;
    }
    if (written.contains(QStringLiteral("pdf")))
        printLine(QStringLiteral("wrote %1 (%2 pages)")
                      .arg(written[QStringLiteral("pdf")].toString())
                      .arg(written[QStringLiteral("pages")].toInt()));
    for (const char* key : {"html", "csv"})
        if (written.contains(QLatin1String(key)))
            printLine(
                QStringLiteral("wrote %1/ (%2 files)")
                    .arg(written[QLatin1String(key)].toString())
                    .arg(written[QLatin1String(key) + QStringLiteral("_files")].toArray().size()));
    if (data.diagnosis.not_applicable.isEmpty())
        printLine(QStringLiteral("verdict: ") + data.diagnosis.result.verdict);
    return 0;
}

}  // namespace driftlab::cli
