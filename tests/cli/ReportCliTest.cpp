// driftlab-cli report: the acceptance report read back the way a customer
// reads it (pdftotext, pdftoppm from poppler-utils) and checked against the
// commands whose figures it reports (iso230-2, diagnose, compare, compensate).
#include <gtest/gtest.h>

#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include "core/bundle/BundleError.h"
#include "core/bundle/CsvTable.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

/// The rows of a CSV of the report, by column name.
std::vector<std::map<QString, QString>> csvRows(const QString& path) {
    auto file = std::make_unique<QFile>(path);
    EXPECT_TRUE(file->open(QIODevice::ReadOnly)) << qPrintable(path);
    std::vector<std::map<QString, QString>> rows;
    try {
        bundle::CsvTable table(std::move(file), path);
        while (table.next()) {
            std::map<QString, QString> row;
            for (std::size_t c = 0; c < table.header().size(); ++c)
                row[table.header()[c]] = table.text(int(c));
            rows.push_back(row);
        }
    } catch (const bundle::BundleException& e) {
        ADD_FAILURE() << qPrintable(e.error.toString());
    }
    return rows;
}

QJsonObject jsonOf(const CliResult& r) {
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return QJsonDocument::fromJson(r.out).object();
}

/// The printed value of each ISO 230-2 axis quantity in the PDF's axis table,
/// by its JSON key (the table's Key column).
std::map<QString, QString> printedAxisValues(const QString& text) {
    const qsizetype from = text.indexOf(QStringLiteral("Axis values"));
    const qsizetype to = text.indexOf(QStringLiteral("Per target"), from);
    std::map<QString, QString> values;
    for (const QString& line : text.mid(from, to - from).split(QLatin1Char('\n'))) {
        const QStringList tokens = line.simplified().split(QLatin1Char(' '));
        if (tokens.size() >= 4 && tokens[1].contains(QRegularExpression(QStringLiteral("^[A-Z]"))))
            values[tokens[1]] = tokens.last();
    }
    return values;
}

const QStringList kAxisKeys{"B",      "B_mean", "R_up", "R_down", "R",      "E_up",
                            "E_down", "E",      "M",    "A_up",   "A_down", "A"};

}  // namespace

// A few minutes: the report compares every model and diagnoses the campaign,
// and `diagnose` runs once more to be compared with.
TEST(ReportCli, pdfAndCsvOfASimulatedCampaignAgreeWithTheCommandsTheyReport) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("campaign"));
    ASSERT_EQ(
        runCli({"simulate", "--out", bundle, "--seed", "2", "--effect", "forced_convection=0.05"})
            .exitCode,
        0);
    const QString pdf = dir.filePath(QStringLiteral("report.pdf"));
    const QString csv = dir.filePath(QStringLiteral("csv"));
    const QJsonObject report = jsonOf(runCli(
        {"report", bundle, "--pdf", pdf, "--csv", csv, "--operator", "A. Tester", "--json"}));
    const QString run = report["iso230_2"].toObject()["run"].toString();
    ASSERT_FALSE(run.isEmpty());
    const QJsonObject iso = jsonOf(runCli({"iso230-2", bundle, "--run", run, "--json"}));
    const QJsonObject diagnosis = jsonOf(runCli({"diagnose", bundle, "--json"}));

    // The PDF says what the commands say, to its printed precision.
    const QString text = pdfText(pdf);
    const std::map<QString, QString> printed = printedAxisValues(text);
    for (const QString& key : kAxisKeys) {
        ASSERT_TRUE(printed.count(key)) << qPrintable(key) << "\n" << qPrintable(text.left(4000));
        EXPECT_EQ(printed.at(key), QString::number(iso[key].toDouble(), 'f', 3)) << qPrintable(key);
    }
    const QString verdict = diagnosis["verdict"].toString();
    EXPECT_EQ(verdict, QStringLiteral("forced_convection"));
    EXPECT_TRUE(text.contains(QStringLiteral("Verdict: ") + verdict));
    EXPECT_EQ(report["verdict"].toString(), verdict);
    EXPECT_TRUE(text.contains(QStringLiteral("A. Tester")));
    EXPECT_TRUE(text.contains(QStringLiteral(DRIFTLAB_VERSION)));
    EXPECT_TRUE(text.contains(QStringLiteral("ISO 230-2:2014")));

    // Every page has something on it, and there are as many as the footer says.
    const QRegularExpressionMatch of =
        QRegularExpression(QStringLiteral("page 1 of (\\d+)")).match(text);
    ASSERT_TRUE(of.hasMatch());
    const int pages = of.captured(1).toInt();
    EXPECT_EQ(report["written"].toObject()["pages"].toInt(), pages);
    EXPECT_GE(pages, 6);  // the cover and one page per section at least
    const QString images = dir.filePath(QStringLiteral("pages"));
    QDir().mkpath(images);
    QProcess ppm;
    ppm.start(QStringLiteral("pdftoppm"),
              {QStringLiteral("-r"), QStringLiteral("40"), QStringLiteral("-png"), pdf,
               images + QStringLiteral("/page")});
    ASSERT_TRUE(ppm.waitForFinished(120'000));
    ASSERT_EQ(ppm.exitCode(), 0);
    const QStringList pngs = QDir(images).entryList({QStringLiteral("*.png")}, QDir::Files);
    EXPECT_EQ(pngs.size(), pages);
    for (const QString& png : pngs) {
        const QImage page(QDir(images).filePath(png));
        ASSERT_FALSE(page.isNull());
        qint64 inked = 0;
        for (int y = 0; y < page.height(); ++y)
            for (int x = 0; x < page.width(); ++x)
                if (qGray(page.pixel(x, y)) < 200) ++inked;
        EXPECT_GT(double(inked) / (page.width() * page.height()), 0.004) << qPrintable(png);
    }

    // The CSV tables hold the commands' values at full precision.
    for (const auto& row : csvRows(csv + QStringLiteral("/iso230-2-axis.csv")))
        EXPECT_DOUBLE_EQ(row.at("Value µm").toDouble(), iso[row.at("Key")].toDouble())
            << qPrintable(row.at("Key"));
    // The standards compared are the columns of `iso230-2 --standard all`:
    // a value where the standard defines it, "-" where it does not.
    const QJsonObject standards =
        jsonOf(runCli({"iso230-2", bundle, "--run", run, "--standard", "all", "--json"}));
    const auto compared = csvRows(csv + QStringLiteral("/iso230-2-standards.csv"));
    EXPECT_EQ(compared.size(), kAxisKeys.size());
    ASSERT_EQ(standards["standards"].toArray().size(), 5);
    for (const QJsonValue& each : standards["standards"].toArray()) {
        const QString title = each.toObject()["standard"].toString();
        const QJsonObject values = each.toObject()["values"].toObject();
        for (const auto& row : compared) {
            ASSERT_TRUE(row.count(title)) << "no column " << qPrintable(title);
            const QString& cell = row.at(title);
            if (values.contains(row.at("Key")))
                EXPECT_DOUBLE_EQ(cell.toDouble(), values[row.at("Key")].toDouble())
                    << qPrintable(title) << " " << qPrintable(row.at("Key"));
            else
                EXPECT_EQ(cell, QStringLiteral("-")) << qPrintable(title);
        }
    }
    const auto findings = csvRows(csv + QStringLiteral("/diagnosis-findings.csv"));
    const QJsonArray jsonFindings = diagnosis["findings"].toArray();
    ASSERT_EQ(findings.size(), std::size_t(jsonFindings.size()));
    for (std::size_t i = 0; i < findings.size(); ++i) {
        const QJsonObject f = jsonFindings[int(i)].toObject();
        EXPECT_EQ(findings[i].at("Cause"), f["cause"].toString());
        EXPECT_DOUBLE_EQ(findings[i].at("Held-out gain").toDouble(),
                         f["gain"].toObject()["reduction"].toDouble());
        EXPECT_DOUBLE_EQ(findings[i].at("Confidence").toDouble(), f["confidence"].toDouble());
    }
    const QJsonObject compare = jsonOf(runCli({"compare", bundle, "--models", "mlr", "--json"}));
    const QJsonArray runs = compare["runs"].toArray();
    const QJsonArray matrix = compare["models"].toObject()["mlr"].toObject()["rms_um"].toArray();
    const auto mlr = csvRows(csv + QStringLiteral("/models-mlr.csv"));
    ASSERT_EQ(mlr.size(), std::size_t(runs.size()));
    for (int i = 0; i < runs.size(); ++i)
        for (int j = 0; j < runs.size(); ++j)
            EXPECT_DOUBLE_EQ(mlr[std::size_t(i)].at(runs[j].toString()).toDouble(),
                             matrix[i].toArray()[j].toDouble());
    const QString table = dir.filePath(QStringLiteral("table.csv"));
    ASSERT_EQ(
        runCli({"compensate", bundle, "--run", run, "--format", "csv", "--out", table}).exitCode,
        0);
    const auto exported = csvRows(table);
    const auto reported = csvRows(csv + QStringLiteral("/compensation-table.csv"));
    ASSERT_EQ(exported.size(), reported.size());
    for (std::size_t i = 0; i < exported.size(); ++i) {
        EXPECT_NEAR(reported[i].at("position_mm").toDouble(),
                    exported[i].at("position_mm").toDouble(), 0.00005);
        EXPECT_NEAR(reported[i].at("correction_plus_um").toDouble(),
                    exported[i].at("correction_um").toDouble(), 0.0005);
    }
}

// The ISO 230-2 procedure on the simulated rig gives one positioning run:
// the sections it has no data for say so in one line, and the report is made.
TEST(ReportCli, aPositioningOnlyCampaignSaysWhichSectionsDoNotApply) {
    QTemporaryDir dir;
    const QString db = dir.filePath(QStringLiteral("lab.sqlite"));
    const CliResult ran = runCli({"run", "--procedure",
                                  DRIFTLAB_SOURCE_DIR "/resources/procedures/iso230-2-x-axis.json",
                                  "--rig", "sim", "--db", db});
    ASSERT_EQ(ran.exitCode, 0) << ran.err.constData();
    const QString id = QString::fromUtf8(ran.out.trimmed());
    const QString pdf = dir.filePath(QStringLiteral("report.pdf"));
    const QString html = dir.filePath(QStringLiteral("html"));
    const QJsonObject report = jsonOf(
        runCli({"report", "--db", db, "--campaign", id, "--pdf", pdf, "--html", html, "--json"}));
    const QString text = pdfText(pdf);
    EXPECT_TRUE(text.contains(QStringLiteral("Not applicable: no moving, spindle or ETVE run.")));
    EXPECT_TRUE(text.contains(QStringLiteral("Not applicable: no model comparison")));
    EXPECT_TRUE(text.contains(QStringLiteral("Not applicable: no diagnosis")));
    EXPECT_TRUE(text.contains(QStringLiteral("Operator")) && text.contains("not given"));
    EXPECT_TRUE(report["iso230_2"].isObject());
    EXPECT_TRUE(report["compensation"].isObject());
    const QJsonObject notApplicable = report["not_applicable"].toObject();
    EXPECT_TRUE(notApplicable.contains("iso230_3"));
    EXPECT_TRUE(notApplicable.contains("models"));
    EXPECT_TRUE(notApplicable.contains("diagnosis"));
    EXPECT_FALSE(notApplicable.contains("iso230_2"));
    // The HTML alternative: an index and its plots, each a real image.
    QFile index(html + QStringLiteral("/index.html"));
    ASSERT_TRUE(index.open(QIODevice::ReadOnly));
    const QString page = QString::fromUtf8(index.readAll());
    EXPECT_TRUE(page.contains(QStringLiteral("no moving, spindle or ETVE run")));
    const QJsonArray files = report["written"].toObject()["html_files"].toArray();
    EXPECT_TRUE(files.contains(QStringLiteral("iso230-2.png")));
    for (const auto& f : files) {
        if (f.toString().endsWith(QStringLiteral(".png"))) {
            EXPECT_FALSE(QImage(html + '/' + f.toString()).isNull()) << qPrintable(f.toString());
        }
    }
}

TEST(ReportCli, badInputFailsWithOneLineAndLeavesNoFile) {
    QTemporaryDir dir;
    const QString example =
        QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/examples/x-axis-moving-state");
    const QString db = dir.filePath(QStringLiteral("lab.sqlite"));
    ASSERT_EQ(runCli({"import", example, "--db", db}).exitCode, 0);
    const QString pdf = dir.filePath(QStringLiteral("r.pdf"));

    CliResult r = runCli({"report", "--db", db, "--campaign", "99", "--pdf", pdf});
    EXPECT_NE(r.exitCode, 0);
    EXPECT_TRUE(reason(r.err).contains("99")) << r.err.constData();
    EXPECT_FALSE(QFile::exists(pdf));

    const QString nowhere = dir.filePath(QStringLiteral("no/such/folder/r.pdf"));
    r = runCli({"report", example, "--pdf", nowhere});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(reason(r.err).contains("does not exist")) << r.err.constData();
    EXPECT_FALSE(QFile::exists(nowhere));

    // A file where the folder should be: nothing is written, the file is untouched.
    QFile blocker(dir.filePath(QStringLiteral("file")));
    ASSERT_TRUE(blocker.open(QIODevice::WriteOnly));
    blocker.write("keep");
    blocker.close();
    r = runCli({"report", example, "--pdf", blocker.fileName() + QStringLiteral("/r.pdf"), "--csv",
                dir.filePath(QStringLiteral("csv"))});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(reason(r.err).contains("is not a folder")) << r.err.constData();
    EXPECT_FALSE(QFile::exists(dir.filePath(QStringLiteral("csv"))));

    r = runCli({"report", example});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(reason(r.err).contains("--pdf")) << r.err.constData();

    r = runCli({"report", example, "--run", "S9", "--pdf", pdf});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(reason(r.err).contains("S9")) << r.err.constData();
    EXPECT_FALSE(QFile::exists(pdf));
    // A folder that is not a report is never replaced.
    QDir().mkpath(dir.filePath(QStringLiteral("mine")));
    QFile mine(dir.filePath(QStringLiteral("mine/notes.txt")));
    ASSERT_TRUE(mine.open(QIODevice::WriteOnly));
    mine.close();
    r = runCli({"report", example, "--csv", dir.filePath(QStringLiteral("mine"))});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(QFile::exists(dir.filePath(QStringLiteral("mine/notes.txt"))));
}
