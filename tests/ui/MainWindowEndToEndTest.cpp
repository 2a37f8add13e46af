// The whole campaign through the main window, as a test engineer does it in
// `driftlab`: a new store, the demo set-up (the simulated rig, an effect hidden
// in it), Start on the Run page, then a fit on the Models page, the diagnosis
// naming the hidden effect, its extension adopted, and a compensation table
// exported for LinuxCNC — each result checked in the store or the file.
#include <gtest/gtest.h>

#include <QAction>
#include <QComboBox>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QTabWidget>
#include <QTest>

#include "db/CampaignStore.h"
#include "db/DiagnosisStore.h"
#include "db/ModelFitStore.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/models/FindingsModel.h"
#include "ui/pages/CompensationPage.h"
#include "ui/pages/DiagnosisPage.h"
#include "ui/pages/ModelsPage.h"
#include "ui/pages/RunPage.h"
#include "ui/pages/SetupPage.h"
#include "ui/shell/BackgroundJob.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/RunController.h"
#include "ui/shell/Session.h"
#include "ui/widgets/PlotView.h"
#include "ui/widgets/TableExportPanel.h"

using namespace driftlab;

TEST(MainWindowEndToEnd, setUpRunFitDiagnoseTheHiddenEffectAdoptAndExportATable) {
    QTemporaryDir dir;
    ui::MainWindow window;
    window.show();
    const QString store = dir.filePath(QStringLiteral("lab.sqlite"));
    ASSERT_TRUE(window.openStore(store, true, false));

    // Set-up: the demo fills the page for the simulated rig; run as fast as it goes.
    window.setupPage()->loadDemo();
    ASSERT_TRUE(window.setupPage()->demoBannerShown());
    ui::RunSetup setup = window.session().runSetup();
    ASSERT_EQ(setup.rig, QStringLiteral("sim"));
    setup.speedup = 0;
    window.session().setRunSetup(setup);

    // Run: the tool bar's Start; the page checks, then the engine logs.
    window.pages()->setCurrentWidget(window.runPage());
    ASSERT_TRUE(window.runPage()->startAction()->isEnabled());
    window.runPage()->startAction()->trigger();
    ui::RunController& run = window.runPage()->controller();
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return run.state() == engine::EngineState::Finished && !run.active(); }, 120'000))
        << int(run.state());
    ASSERT_TRUE(QTest::qWaitFor([&] { return window.session().campaignId().has_value(); }, 10'000));
    const qint64 campaignId = *window.session().campaignId();

    // Models: fit with the page's defaults; the fit is stored.
    window.pages()->setCurrentWidget(window.modelsPage());
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return window.modelsPage()->fitButton()->isEnabled(); }, 30'000));
    QTest::mouseClick(window.modelsPage()->fitButton(), Qt::LeftButton);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !window.modelsPage()->job()->isRunning(); }, 120'000));
    // Diagnosis: what the physical model misses on these runs, which is what the demo hid.
    ui::DiagnosisPage* diagnosis = window.diagnosisPage();
    window.pages()->setCurrentWidget(diagnosis);
    ASSERT_TRUE(QTest::qWaitFor([&] { return diagnosis->diagnoseButton()->isEnabled(); }, 30'000));
    QTest::mouseClick(diagnosis->diagnoseButton(), Qt::LeftButton);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !diagnosis->job()->isRunning(); }, 300'000));
    const ui::FindingsModel* findings = diagnosis->findingsModel();
    const int verdict = findings->verdictRow();
    ASSERT_GE(verdict, 0) << diagnosis->status().toStdString();
    EXPECT_EQ(findings->index(verdict, ui::FindingsModel::Cause).data().toString(),
              ui::SetupPage::demoHiddenCause());
    EXPECT_GT(findings->index(verdict, ui::FindingsModel::Gain).data().toDouble(), 0);
    EXPECT_EQ(diagnosis->beforeAfter()->curveCount(), 3);  // measured, base, with the extension

    // Adopt: the verdict's row is selected; its extension is kept as a fit.
    ASSERT_TRUE(diagnosis->adoptButton()->isEnabled()) << diagnosis->status().toStdString();
    QTest::mouseClick(diagnosis->adoptButton(), Qt::LeftButton);
    {
        QString error;
        auto db = db::CampaignStore::open(store, db::StoreAccess::ReadOnly, &error);
        ASSERT_TRUE(db) << error.toStdString();
        const auto fits = db::modelFits(*db, campaignId);
        ASSERT_EQ(fits.size(), 2u) << window.modelsPage()->status().toStdString();
        EXPECT_EQ(fits[1].model,
                  QStringLiteral("heat-transfer+") + ui::SetupPage::demoHiddenCause())
            << diagnosis->status().toStdString();
        const auto stored = db::diagnoses(*db, campaignId);
        ASSERT_EQ(stored.size(), 1u);
        EXPECT_EQ(stored[0].verdict, ui::SetupPage::demoHiddenCause());
        EXPECT_EQ(stored[0].adopted_fit_id, std::optional<qint64>(fits[1].id));
    }

    // Compensation: the table of the first positioning run, exported for LinuxCNC.
    window.pages()->setCurrentWidget(window.compensationPage());
    ui::CompensationPage* comp = window.compensationPage();
    ASSERT_TRUE(QTest::qWaitFor([&] { return comp->runBox()->count() > 0; }, 30'000));
    ui::TableExportPanel* exporter = comp->exportPanel();
    exporter->formatBox()->setCurrentIndex(
        exporter->formatBox()->findText(QStringLiteral("linuxcnc")));
    const QString table = dir.filePath(QStringLiteral("x.comp"));
    exporter->pathEdit()->setText(table);
    ASSERT_TRUE(QTest::qWaitFor([&] { return exporter->exportButton()->isEnabled(); }, 10'000));
    QTest::mouseClick(exporter->exportButton(), Qt::LeftButton);
    ASSERT_TRUE(QTest::qWaitFor([&] { return QFile::exists(table); }, 10'000));
    QFile file(table);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    // LinuxCNC COMP_FILE: "nominal forward reverse", one line per point.
    const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
    EXPECT_GE(lines.size(), 5);
    EXPECT_EQ(lines.front().split(' ').size(), 3) << lines.front().constData();
}
