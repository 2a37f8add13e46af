// Screenshots of the ISO 230-3 and sensor-health pages with data, for the
// documentation: run under a real X server with DRIFTLAB_SCREENSHOT_DIR set,
//   DRIFTLAB_SCREENSHOT_DIR=docs/images xvfb-run -a -s "-screen 0 1280x800x24"
//     build/tests/ui/ui_drift_health_tests --gtest_filter='DriftHealthScreenshots.*'
// (one command line). Skipped otherwise.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QItemSelectionModel>
#include <QPushButton>
#include <QTabWidget>
#include <QTableView>
#include <QTest>

#include "tests/ui/ShortedSensorStore.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/models/SensorFlagModel.h"
#include "ui/pages/Iso230_3Page.h"
#include "ui/pages/SensorHealthPage.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/Session.h"

using namespace driftlab;
using namespace driftlab::test;

TEST(DriftHealthScreenshots, iso230_3AndSensorHealthPagesWithData) {
    const QString out = qEnvironmentVariable("DRIFTLAB_SCREENSHOT_DIR");
    if (out.isEmpty()) GTEST_SKIP() << "set DRIFTLAB_SCREENSHOT_DIR to take the screenshots";
    QTemporaryDir dir;
    qint64 campaign = 0;
    const QString example = importExample(dir, &campaign);

    ui::MainWindow window;
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(window.openStore(example, false, false));
    ui::Iso230_3Page* iso = window.iso230_3Page();
    QSignalSpy evaluated(iso, &ui::Iso230_3Page::evaluated);
    window.session().selectCampaign(campaign);
    ASSERT_TRUE(waitFor(evaluated));
    window.pages()->setCurrentWidget(iso);
    QTest::qWait(300);
    EXPECT_TRUE(window.grab().save(out + QStringLiteral("/gui-iso230-3.png")));

    // The shorted campaign, with T_air also frozen for 25 min of S1 (its jump
    // onto the frozen value is a rate the air cannot have), checked; the
    // rate flag is kept, the others left out.
    QTemporaryDir healthDir;
    const QString bundle = shortedSensorBundle(healthDir);
    setSamples(bundle, "T_air", 5000, 6500, "21.30");
    const QString db = importedStore(healthDir, bundle);
    ui::SensorHealthPage* health = window.sensorHealthPage();
    QSignalSpy shown(health, &ui::SensorHealthPage::flagsShown);
    ASSERT_TRUE(window.openStore(db, false, false));
    window.session().selectCampaign(1);
    window.pages()->setCurrentWidget(health);
    ASSERT_TRUE(waitFor(shown));
    health->runBox()->setCurrentIndex(health->runBox()->findData(QStringLiteral("S1")));
    shown.clear();
    health->checkButton()->click();
    ASSERT_TRUE(waitFor(shown));
    const ui::SensorFlagModel* flags = health->flagModel();
    for (int row = 0; row < flags->rowCount(); ++row)
        if (flags->data(flags->index(row, ui::SensorFlagModel::Kind), Qt::UserRole) ==
            QStringLiteral("rate_of_change"))
            health->flagView()->selectRow(row);
    shown.clear();
    health->keepButton()->click();
    ASSERT_TRUE(waitFor(shown));
    EXPECT_EQ(flags->rowCount(), 3);
    QTest::qWait(300);
    EXPECT_TRUE(window.grab().save(out + QStringLiteral("/gui-sensor-health.png")));
}
