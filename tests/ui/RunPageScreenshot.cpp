// The Run page as a user sees it during a run, saved to the PNG named by
// DRIFTLAB_SCREENSHOT_DIR (run under xvfb-run for docs/images; skipped otherwise).
#include <gtest/gtest.h>

#include <QAction>
#include <QDir>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include "ui/pages/RunPage.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/RunController.h"
#include "ui/shell/Session.h"

using namespace driftlab;

TEST(RunPageScreenshot, duringAnIso230_3Run) {
    const QString out = qEnvironmentVariable("DRIFTLAB_SCREENSHOT_DIR");
    if (out.isEmpty()) GTEST_SKIP() << "DRIFTLAB_SCREENSHOT_DIR not set";
    QTemporaryDir dir;
    ui::MainWindow window;
    QString error;
    ASSERT_TRUE(
        window.session().openStore(dir.filePath(QStringLiteral("lab.sqlite")), true, &error));
    ui::RunSetup setup;
    const auto procedure = procedures::loadProcedureFile(
        QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/procedures/iso230-3-x-axis.json"), &error);
    ASSERT_TRUE(procedure) << error.toStdString();
    setup.procedure = *procedure;
    setup.speedup = 1000;
    window.session().setRunSetup(setup);
    window.resize(1280, 800);
    window.show();
    auto* page = window.findChild<ui::RunPage*>();
    ASSERT_TRUE(page);
    window.pages()->setCurrentWidget(page);
    page->startAction()->trigger();
    ASSERT_TRUE(page->controller().active());
    QTest::qWait(7000);
    window.grab().save(QDir(out).filePath(QStringLiteral("gui-run.png")));
    page->abortAction()->trigger();
    page->controller().waitForEnd();
}
