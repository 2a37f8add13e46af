// Screenshots of the Compensation and ISO 230-2 pages with data, for the
// documentation: run under a real X server with DRIFTLAB_SCREENSHOT_DIR set,
//   DRIFTLAB_SCREENSHOT_DIR=docs/images xvfb-run -a -s "-screen 0 1280x800x24"
//     build/tests/ui/ui_compensation_tests --gtest_filter='Screenshots.*'
// (one command line).
// Skipped otherwise.
#include <gtest/gtest.h>

#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QTabWidget>
#include <QTest>

#include "acquisition/sim/SimulatedController.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/pages/CompensationPage.h"
#include "ui/pages/Iso230_2Page.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/Session.h"
#include "ui/widgets/ControllerPanel.h"
#include "ui/widgets/PushConfirmDialog.h"

#include <QDialogButtonBox>

using namespace driftlab;
using namespace driftlab::test;

TEST(Screenshots, compensationAndIso230_2PagesWithData) {
    const QString out = qEnvironmentVariable("DRIFTLAB_SCREENSHOT_DIR");
    if (out.isEmpty()) GTEST_SKIP() << "set DRIFTLAB_SCREENSHOT_DIR to take the screenshots";
    QTemporaryDir dir;
    qint64 campaign = 0;
    const QString db = importExample(dir, &campaign);
    sim::SimulatedController controller;
    QString error;
    ASSERT_TRUE(controller.start(&error)) << qPrintable(error);

    ui::MainWindow window;
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(window.openStore(db, false, false));
    ui::CompensationPage* page = window.compensationPage();
    QSignalSpy updated(page, &ui::CompensationPage::tableUpdated);
    QSignalSpy evaluated(window.iso230_2Page(), &ui::Iso230_2Page::evaluated);
    window.session().selectCampaign(campaign);
    ASSERT_TRUE(waitFor(updated));
    window.pages()->setCurrentWidget(page);
    QTest::mouseClick(page->spacingButton(), Qt::LeftButton);
    page->spacingBox()->setValue(35);

    // One push applied, then "Read controller" to show the (now zero) change
    // next to a slightly different table.
    ui::ControllerPanel* panel = page->controllerPanel();
    panel->urlEdit()->setText(controller.url());
    QSignalSpy read(panel, &ui::ControllerPanel::activeTableRead);
    QTest::mouseClick(panel->pushButton(), Qt::LeftButton);
    ASSERT_TRUE(waitFor(read));
    QSignalSpy pushed(panel, &ui::ControllerPanel::pushFinished);
    QTest::mouseClick(panel->confirmation()->pushButton(), Qt::LeftButton);
    ASSERT_TRUE(waitFor(pushed));
    page->spacingBox()->setValue(50);
    QTest::mouseClick(panel->readButton(), Qt::LeftButton);
    ASSERT_TRUE(waitFor(read, 2));
    QTest::qWait(200);
    EXPECT_TRUE(window.grab().save(out + QStringLiteral("/gui-compensation.png")));

    ui::Iso230_2Page* iso = window.iso230_2Page();
    ASSERT_TRUE(waitFor(evaluated));
    window.pages()->setCurrentWidget(iso);
    QTest::qWait(200);
    EXPECT_TRUE(window.grab().save(out + QStringLiteral("/gui-iso230-2.png")));

    // The acceptance of the same run against the example specification.
    ASSERT_TRUE(iso->loadSpecification(
        QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/examples/x-axis-acceptance.json")));
    auto* tabs = iso->findChild<QTabWidget*>();
    ASSERT_NE(tabs, nullptr);
    for (int i = 0; i < tabs->count(); ++i)
        if (tabs->tabText(i) == QStringLiteral("Acceptance")) tabs->setCurrentIndex(i);
    QTest::qWait(200);
    EXPECT_TRUE(window.grab().save(out + QStringLiteral("/gui-acceptance.png")));
}
