// Screenshots of the Set-up page's channels in the demo state and of the
// whole main window, for docs/images (gui-setup.png is the demo autopilot's,
// with every other page). Run under a real X server:
//   DRIFTLAB_SCREENSHOT_DIR=docs/images xvfb-run -a -s "-screen 0 1280x800x24"
//       env QT_QPA_PLATFORM=xcb build/tests/ui/ui_setup_tests --gtest_filter='*Screenshot*'
// Skipped when DRIFTLAB_SCREENSHOT_DIR is not set.
#include <gtest/gtest.h>

#include <QDir>
#include <QListWidget>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTest>

#include "tests/support/CliRunner.h"
#include "ui/pages/SetupPage.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/Session.h"

namespace driftlab::ui {
namespace {

TEST(SetupScreenshot, demoSetupPageAndMainWindow) {
    const QString out = qEnvironmentVariable("DRIFTLAB_SCREENSHOT_DIR");
    if (out.isEmpty()) GTEST_SKIP() << "DRIFTLAB_SCREENSHOT_DIR not set";
    MainWindow window;
    window.resize(1280, 800);
    window.show();
    window.startDemo();
    // A campaign in the tree, as after the demo's first run.
    const test::CliResult imported =
        test::runCli({QStringLiteral("import"), test::simulatedCampaign(QStringLiteral("S1,S4"), 1),
                      QStringLiteral("--db"), window.session().storePath()});
    ASSERT_EQ(imported.exitCode, 0) << imported.err.constData();
    window.refreshCampaignTree();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    QTest::qWait(300);
    ASSERT_TRUE(window.grab().save(QDir(out).filePath(QStringLiteral("gui-main.png"))));
    SetupPage* page = window.setupPage();
    page->sections()->setCurrentRow(SetupPage::ChannelsSection);
    QTest::qWait(100);
    ASSERT_TRUE(page->grab().save(QDir(out).filePath(QStringLiteral("gui-setup-channels.png"))));
}

}  // namespace
}  // namespace driftlab::ui
