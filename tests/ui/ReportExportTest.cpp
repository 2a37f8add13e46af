// File → Export report… on a real store made by the real CLI: the PDF of
// the selected campaign is written, and Cancel leaves no file.
#include <gtest/gtest.h>

#include <QAction>
#include <QFile>
#include <QProcess>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include "tests/ui/UiTestSupport.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/ReportExport.h"
#include "ui/shell/Session.h"

using namespace driftlab;

namespace {

std::unique_ptr<ui::MainWindow> windowOnExample(const QTemporaryDir& dir) {
    qint64 id = 0;
    const QString store = test::importExample(dir, &id);
    auto window = std::make_unique<ui::MainWindow>();
    EXPECT_TRUE(window->openStore(store, false, false));
    window->show();
    window->session().selectCampaign(id);
    return window;
}

}  // namespace

TEST(ReportExport, writesThePdfOfTheSelectedCampaign) {
    QTemporaryDir dir;
    auto window = windowOnExample(dir);
    auto* action = window->findChild<QAction*>(QStringLiteral("ExportReportAction"));
    ASSERT_TRUE(action);
    EXPECT_TRUE(action->isEnabled());
    const QString pdf = dir.filePath(QStringLiteral("report.pdf"));
    QSignalSpy finished(window->reportExport(), &ui::ReportExport::finished);
    ASSERT_TRUE(window->reportExport()->start(pdf));
    EXPECT_TRUE(window->reportExport()->progressDialog()->isVisible());
    ASSERT_TRUE(test::waitFor(finished));
    EXPECT_TRUE(finished[0][0].toBool()) << qPrintable(finished[0][1].toString());
    EXPECT_FALSE(window->reportExport()->progressDialog()->isVisible());

    QFile file(pdf);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_TRUE(file.read(5) == "%PDF-");
    const QString content = test::pdfText(pdf);
    QString error;
    const auto campaign = window->session().loadCampaign(&error);
    ASSERT_TRUE(campaign);
    EXPECT_TRUE(content.contains(campaign->name));
    EXPECT_TRUE(content.contains(QStringLiteral("ISO 230-2")));
    EXPECT_TRUE(content.contains(QStringLiteral("page 1 of")));
}

TEST(ReportExport, cancelLeavesNoFile) {
    QTemporaryDir dir;
    auto window = windowOnExample(dir);
    const QString pdf = dir.filePath(QStringLiteral("report.pdf"));
    QSignalSpy finished(window->reportExport(), &ui::ReportExport::finished);
    ASSERT_TRUE(window->reportExport()->start(pdf));
    EXPECT_TRUE(window->reportExport()->isRunning());
    auto* cancel = window->reportExport()->progressDialog()->findChild<QPushButton*>();
    ASSERT_TRUE(cancel);
    QTest::mouseClick(cancel, Qt::LeftButton);
    ASSERT_TRUE(test::waitFor(finished));
    EXPECT_FALSE(finished[0][0].toBool());
    EXPECT_EQ(finished[0][1].toString(), QStringLiteral("cancelled"));
    EXPECT_FALSE(window->reportExport()->isRunning());
    EXPECT_FALSE(QFile::exists(pdf));
    EXPECT_TRUE(QDir(dir.path()).entryList({QStringLiteral("*.pdf")}).isEmpty());
}

// The pages are drawn one per turn of the event loop: Cancel between them
// discards the half-written PDF.
TEST(ReportExport, cancelWhileThePagesAreDrawnLeavesNoFile) {
    QTemporaryDir dir;
    auto window = windowOnExample(dir);
    const QString pdf = dir.filePath(QStringLiteral("report.pdf"));
    QSignalSpy finished(window->reportExport(), &ui::ReportExport::finished);
    QProgressDialog* dialog = window->reportExport()->progressDialog();
    ASSERT_TRUE(window->reportExport()->start(pdf));
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return dialog->labelText().startsWith(QStringLiteral("Writing")); }, 60'000));
    ASSERT_TRUE(finished.isEmpty()) << "the pages were drawn before the test could cancel";
    QTest::mouseClick(dialog->findChild<QPushButton*>(), Qt::LeftButton);
    ASSERT_TRUE(test::waitFor(finished));
    EXPECT_FALSE(finished[0][0].toBool());
    EXPECT_EQ(finished[0][1].toString(), QStringLiteral("cancelled"));
    EXPECT_FALSE(QFile::exists(pdf));
    EXPECT_TRUE(QDir(dir.path()).entryList({QStringLiteral("*.pdf")}).isEmpty());
}

TEST(ReportExport, needsASelectedCampaign) {
    QTemporaryDir dir;
    ui::MainWindow window;
    auto* action = window.findChild<QAction*>(QStringLiteral("ExportReportAction"));
    ASSERT_TRUE(action);
    EXPECT_FALSE(action->isEnabled());
    EXPECT_FALSE(window.reportExport()->start(dir.filePath(QStringLiteral("r.pdf"))));
}
