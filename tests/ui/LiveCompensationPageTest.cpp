// The Live page through its widgets, on stores made by the real CLI: a
// replay sent to the simulated controller over real Modbus TCP follows
// `driftlab-cli live --push` on the same store and run update for update,
// an extension adopted on the Diagnosis page is offered (the newest chosen)
// and runs as `live --model` does, a model worse than no compensation is
// refused on the page (shown, with
// nothing written to the controller) unless the override is ticked, and Stop
// ends a paced replay with the controller holding what the table shows.
#include <gtest/gtest.h>

#include <QAbstractItemModelTester>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QJsonArray>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTest>

#include "acquisition/sim/SimulatedController.h"
#include "db/ModelFitStore.h"
#include "tests/support/PureNoise.h"
#include "tests/ui/ModelsTestSupport.h"
#include "ui/models/LiveUpdatesModel.h"
#include "ui/pages/LiveCompensationPage.h"
#include "ui/shell/MainWindow.h"
#include "ui/shell/Session.h"
#include "ui/widgets/LiveOffsetPlot.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

/// A simulated three-state campaign whose every reading after cycle 0 is its
/// cycle-0 reading plus white noise of 1 µm (no thermal error at all), as a
/// store: any model fitted on it does worse than none where it was not fitted.
QString noiseStore(const QTemporaryDir& dir) {
    const QString bundle = dir.filePath(QStringLiteral("noise"));
    const QString store = dir.filePath(QStringLiteral("noise.db"));
    EXPECT_EQ(runCli({QStringLiteral("simulate"), QStringLiteral("--out"), bundle,
                      QStringLiteral("--runs"), QStringLiteral("S1,S2,S3"),
                      QStringLiteral("--seed"), QStringLiteral("5")})
                  .exitCode,
              0);
    replaceDriftByNoise(bundle);
    EXPECT_EQ(runCli({QStringLiteral("import"), bundle, QStringLiteral("--db"), store}).exitCode,
              0);
    return store;
}

/// A main window on `store`, campaign 1 selected and the Live tab shown.
std::unique_ptr<ui::MainWindow> liveWindowOn(const QString& store) {
    auto window = std::make_unique<ui::MainWindow>();
    EXPECT_TRUE(window->openStore(store, false, false));
    ui::LiveCompensationPage* page = window->liveCompensationPage();
    window->pages()->setCurrentWidget(page);
    window->resize(1280, 800);
    window->show();
    QSignalSpy shown(page, &ui::LiveCompensationPage::campaignShown);
    window->session().selectCampaign(1);
    EXPECT_TRUE(shown.count() > 0 || shown.wait(60'000));
    return window;
}

/// Sets the page up to replay `run` fitted on `train`, sent to `controller`
/// (empty: a rehearsal), every 300 s of the run.
void setUp(ui::LiveCompensationPage& page, const QString& run, const QStringList& train,
           const QString& controller) {
    page.runBox()->setCurrentText(run);
    for (int i = 0; i < page.trainList()->count(); ++i) {
        QListWidgetItem* item = page.trainList()->item(i);
        item->setCheckState(train.contains(item->text()) ? Qt::Checked : Qt::Unchecked);
    }
    page.intervalBox()->setValue(300);
    const auto kind = controller.isEmpty() ? ui::LiveCompensationPage::Rehearsal
                                           : ui::LiveCompensationPage::ModbusRegisters;
    page.controllerBox()->setCurrentIndex(page.controllerBox()->findData(kind));
    page.urlEdit()->setText(controller);
}

/// Replays as setUp() says, to the end.
void replay(ui::LiveCompensationPage& page, const QString& run, const QStringList& train,
            const QString& controller) {
    setUp(page, run, train, controller);
    QSignalSpy finished(&page, &ui::LiveCompensationPage::runFinished);
    QTest::mouseClick(page.startButton(), Qt::LeftButton);
    ASSERT_TRUE(finished.wait(300'000)) << page.statusLabel()->text().toStdString();
}

}  // namespace

TEST(LiveCompensationPage, aReplaySentToTheControllerFollowsTheCliUpdateForUpdate) {
    QTemporaryDir dir;
    const QString store =
        simulatedStore(dir, {QStringLiteral("--runs"), QStringLiteral("S1,S3")}, "live.db");
    sim::SimulatedController cliController, pageController;
    QString error;
    ASSERT_TRUE(cliController.start(&error)) << error.toStdString();
    ASSERT_TRUE(pageController.start(&error)) << error.toStdString();
    const CliResult cli =
        runCli({QStringLiteral("live"), QStringLiteral("--db"), store, QStringLiteral("--campaign"),
                QStringLiteral("1"), QStringLiteral("--run"), QStringLiteral("S3"),
                QStringLiteral("--train"), QStringLiteral("S1"), QStringLiteral("--interval-s"),
                QStringLiteral("300"), QStringLiteral("--push"), cliController.url(),
                QStringLiteral("--json")});
    ASSERT_EQ(cli.exitCode, 0) << cli.err.constData();
    const QJsonArray expected = json(cli)[QStringLiteral("updates")].toArray();
    ASSERT_GT(expected.size(), 3);

    auto window = liveWindowOn(store);
    ui::LiveCompensationPage& page = *window->liveCompensationPage();
    // Rows appended one update at a time keep the model consistent for its views.
    QAbstractItemModelTester tester(page.updatesModel(),
                                    QAbstractItemModelTester::FailureReportingMode::Fatal);
    replay(page, QStringLiteral("S3"), {QStringLiteral("S1")}, pageController.url());
    EXPECT_FALSE(page.harmLabel()->isVisible());
    const std::vector<compensation::LiveUpdate>& updates = page.updatesModel()->updates();
    ASSERT_EQ(updates.size(), std::size_t(expected.size()))
        << page.statusLabel()->text().toStdString();
    for (std::size_t i = 0; i < updates.size(); ++i) {
        const QJsonObject u = expected[qsizetype(i)].toObject();
        EXPECT_DOUBLE_EQ(updates[i].time_s, u[QStringLiteral("time_s")].toDouble()) << i;
        EXPECT_DOUBLE_EQ(updates[i].offset_um, u[QStringLiteral("offset_um")].toDouble()) << i;
        EXPECT_EQ(updates[i].limited, u[QStringLiteral("limited")].toBool()) << i;
    }
    // The controllers were told the same: as many sequences, the same last offset.
    for (int address : {2000, 2001, 2002, 2003})
        EXPECT_EQ(pageController.registerValue(address), cliController.registerValue(address))
            << address;
    EXPECT_EQ(page.updatesModel()->rowCount(), expected.size());
    EXPECT_GE(page.plot()->graphCount(), 2);  // the model's correction and the offset sent
    EXPECT_TRUE(page.gateLabel()->text().contains(QStringLiteral("updates applied")))
        << page.gateLabel()->text().toStdString();
    EXPECT_TRUE(page.statusLabel()->text().contains(
        QStringLiteral("%1 updates sent to %2").arg(expected.size()).arg(pageController.url())))
        << page.statusLabel()->text().toStdString();
}

/// Stores a fit of `model` in campaign 1 of `store`, as Adopt on the
/// Diagnosis page does (db::adoptExtension); the Live page needs its name only.
void storeAdoptedFit(const QString& store, const QString& model) {
    QString error;
    auto opened = db::CampaignStore::open(store, db::StoreAccess::ReadWrite, &error);
    ASSERT_TRUE(opened) << error.toStdString();
    db::ModelFitRecord fit;
    fit.model = model;
    fit.train_runs = {QStringLiteral("S1")};
    ASSERT_TRUE(db::storeModelFit(*opened, 1, fit, &error)) << error.toStdString();
}

TEST(LiveCompensationPage, anAdoptedExtensionIsOfferedAndRunsAsTheCliModelOptionDoes) {
    QTemporaryDir dir;
    const QString store =
        simulatedStore(dir,
                       {QStringLiteral("--runs"), QStringLiteral("S1,S4"),
                        QStringLiteral("--effect"), QStringLiteral("motor_heat=0.5")},
                       "adopted.db");
    const QString extension = QStringLiteral("heat-transfer+motor_heat");
    storeAdoptedFit(store, extension);
    const CliResult cli = runCli(
        {QStringLiteral("live"), QStringLiteral("--db"), store, QStringLiteral("--campaign"),
         QStringLiteral("1"), QStringLiteral("--run"), QStringLiteral("S4"),
         QStringLiteral("--train"), QStringLiteral("S1"), QStringLiteral("--model"), extension,
         QStringLiteral("--interval-s"), QStringLiteral("300"), QStringLiteral("--json")});
    ASSERT_EQ(cli.exitCode, 0) << cli.err.constData();
    EXPECT_EQ(json(cli)[QStringLiteral("model")].toString(), extension);
    const QJsonArray expected = json(cli)[QStringLiteral("updates")].toArray();
    ASSERT_GT(expected.size(), 3);

    auto window = liveWindowOn(store);
    ui::LiveCompensationPage& page = *window->liveCompensationPage();
    ASSERT_EQ(page.modelBox()->count(), 2);
    EXPECT_EQ(page.modelBox()->itemText(0), QStringLiteral("heat-transfer"));
    EXPECT_EQ(page.modelBox()->currentText(), extension);
    replay(page, QStringLiteral("S4"), {QStringLiteral("S1")}, QString());
    const std::vector<compensation::LiveUpdate>& updates = page.updatesModel()->updates();
    ASSERT_EQ(updates.size(), std::size_t(expected.size()))
        << page.statusLabel()->text().toStdString();
    for (std::size_t i = 0; i < updates.size(); ++i)
        EXPECT_DOUBLE_EQ(updates[i].offset_um,
                         expected[qsizetype(i)].toObject()[QStringLiteral("offset_um")].toDouble())
            << i;
    EXPECT_DOUBLE_EQ(page.updatesModel()->uncertaintyUm(),
                     expected[0].toObject()[QStringLiteral("uncertainty_um")].toDouble());

    // A choice among the listed models stays when the store changes; an
    // extension adopted meanwhile becomes the choice.
    page.modelBox()->setCurrentIndex(0);
    QSignalSpy shown(&page, &ui::LiveCompensationPage::campaignShown);
    window->session().notifyStoreChanged();
    ASSERT_TRUE(shown.wait(60'000));
    EXPECT_EQ(page.modelBox()->currentText(), QStringLiteral("heat-transfer"));
    storeAdoptedFit(store, QStringLiteral("heat-transfer+forced_convection"));
    window->session().notifyStoreChanged();
    ASSERT_TRUE(shown.wait(60'000));
    EXPECT_EQ(page.modelBox()->currentText(), QStringLiteral("heat-transfer+forced_convection"));
    EXPECT_EQ(page.modelBox()->count(), 3);
}

TEST(LiveCompensationPage, aModelWorseThanNoneIsRefusedForTheControllerUnlessOverridden) {
    QTemporaryDir dir;
    const QString store = noiseStore(dir);
    sim::SimulatedController controller;
    QString error;
    ASSERT_TRUE(controller.start(&error)) << error.toStdString();
    auto window = liveWindowOn(store);
    ui::LiveCompensationPage& page = *window->liveCompensationPage();
    const QStringList train{QStringLiteral("S1"), QStringLiteral("S2")};

    replay(page, QStringLiteral("S3"), train, controller.url());
    EXPECT_TRUE(page.harmLabel()->isVisible());
    EXPECT_TRUE(page.harmLabel()->text().contains(QStringLiteral("Refused")))
        << page.harmLabel()->text().toStdString();
    EXPECT_TRUE(page.harmLabel()->text().contains(QStringLiteral("worse than no compensation")));
    EXPECT_EQ(page.updatesModel()->rowCount(), 0);
    EXPECT_EQ(controller.writeRequests(), 0);

    // A rehearsal shows it, and says a controller would refuse it.
    replay(page, QStringLiteral("S3"), train, QString());
    EXPECT_TRUE(page.harmLabel()->isVisible());
    EXPECT_FALSE(page.harmLabel()->text().contains(QStringLiteral("Refused")));
    EXPECT_GT(page.updatesModel()->rowCount(), 0);

    // Overridden: sent.
    page.overrideBox()->setChecked(true);
    replay(page, QStringLiteral("S3"), train, controller.url());
    EXPECT_TRUE(page.harmLabel()->text().contains(QStringLiteral("override")));
    EXPECT_GT(page.updatesModel()->rowCount(), 0);
    EXPECT_EQ(controller.registerValue(2000), page.updatesModel()->rowCount());
}

TEST(LiveCompensationPage, stopEndsTheReplayWithEveryShownUpdateSentAndNoMore) {
    QTemporaryDir dir;
    const QString store =
        simulatedStore(dir, {QStringLiteral("--runs"), QStringLiteral("S1,S3")}, "stop.db");
    sim::SimulatedController controller;
    QString error;
    ASSERT_TRUE(controller.start(&error)) << error.toStdString();
    auto window = liveWindowOn(store);
    ui::LiveCompensationPage& page = *window->liveCompensationPage();
    setUp(page, QStringLiteral("S3"), {QStringLiteral("S1")}, controller.url());
    page.speedupBox()->setValue(300);  // an update a second: time to press Stop
    QSignalSpy shown(&page, &ui::LiveCompensationPage::updateShown);
    QSignalSpy finished(&page, &ui::LiveCompensationPage::runFinished);
    QTest::mouseClick(page.startButton(), Qt::LeftButton);
    ASSERT_TRUE(shown.wait(120'000)) << page.statusLabel()->text().toStdString();
    EXPECT_TRUE(page.isRunning());
    EXPECT_TRUE(page.stopButton()->isEnabled());
    QTest::mouseClick(page.stopButton(), Qt::LeftButton);
    ASSERT_TRUE(finished.wait(60'000));
    EXPECT_FALSE(page.isRunning());
    EXPECT_TRUE(page.statusLabel()->text().startsWith(QStringLiteral("Stopped after")))
        << page.statusLabel()->text().toStdString();
    // Stopped before the end (36 updates), and the controller got what the table shows.
    const int rows = page.updatesModel()->rowCount();
    EXPECT_GT(rows, 0);
    EXPECT_EQ(controller.registerValue(2000), rows);
    EXPECT_TRUE(page.startButton()->isEnabled());
}
