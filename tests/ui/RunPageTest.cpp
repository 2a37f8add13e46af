// The Run page through its actions, on a real store in a temporary folder:
// pause and resume while data arrive, abort, and the checklist refusing an
// invalid procedure and a Modbus device that does not answer; Abort while
// the run is paused on a lost module (the pymodbus peer SIGKILLed).
#include <gtest/gtest.h>

#include <QAction>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLoggingCategory>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>

#include "core/procedures/Procedure.h"
#include "core/procedures/ProcedurePlan.h"
#include "tests/acquisition/DevicePeer.h"
#include "tests/acquisition/LoggedRunSupport.h"
#include "ui/pages/RunPage.h"
#include "ui/shell/RunController.h"
#include "ui/shell/Session.h"
#include "ui/widgets/PreRunChecklist.h"
#include "ui/widgets/RunStatusWidget.h"

using namespace driftlab;
using engine::EngineState;

namespace {

struct RunFixture {
    QTemporaryDir dir;
    ui::Session session;
    QString store = dir.filePath(QStringLiteral("lab.sqlite"));

    explicit RunFixture(double speedup) {
        QString error;
        EXPECT_TRUE(session.openStore(store, true, &error)) << error.toStdString();
        ui::RunSetup setup;
        setup.procedure = test::twoShortMovingStates();
        setup.speedup = speedup;
        session.setRunSetup(setup);
    }
};

std::int64_t rowsShown(const ui::RunController& controller) {
    const auto buffer = controller.liveBuffer();
    return buffer ? buffer->rowCount() : 0;
}

}  // namespace

TEST(RunPage, pauseStopsTheRowsResumeGoesOnAndTheStoreHasTheCompleteRun) {
    RunFixture f(1000);
    ui::RunPage page(f.session);
    ui::RunController& controller = page.controller();
    QSignalSpy finished(&controller, &ui::RunController::finished);
    ASSERT_TRUE(page.startAction()->isEnabled());
    EXPECT_FALSE(page.pauseAction()->isEnabled());
    page.startAction()->trigger();
    ASSERT_TRUE(controller.active()) << page.checklist().problems().join(';').toStdString();
    ASSERT_TRUE(QTest::qWaitFor([&] { return rowsShown(controller) > 50; }, 30000));
    ASSERT_TRUE(QTest::qWaitFor([&] { return page.pauseAction()->isEnabled(); }, 5000));

    page.pauseAction()->trigger();
    ASSERT_TRUE(QTest::qWaitFor([&] { return controller.state() == EngineState::Paused; }, 10000));
    EXPECT_TRUE(page.resumeAction()->isEnabled());
    EXPECT_FALSE(page.pauseAction()->isEnabled());
    const std::int64_t atPause = rowsShown(controller);
    QTest::qWait(500);  // at 1000× that would be 500 s of run time
    EXPECT_EQ(rowsShown(controller), atPause);
    EXPECT_TRUE(page.progressText().contains(QStringLiteral("Run 1 of 2")))
        << page.progressText().toStdString();

    page.resumeAction()->trigger();
    ASSERT_TRUE(finished.wait(120000) || finished.count() == 1);
    EXPECT_TRUE(finished.first().first().toBool());
    EXPECT_EQ(controller.state(), EngineState::Finished);
    EXPECT_EQ(test::runStatuses(f.store),
              (QStringList{QStringLiteral("S1=complete"), QStringLiteral("S2=complete")}));
    // The run's campaign is selected and its runs hold every row.
    QString error;
    const auto campaign = f.session.loadCampaign(&error);
    ASSERT_TRUE(campaign) << error.toStdString();
    ASSERT_EQ(campaign->runs.size(), 2u);
    const auto planned = procedures::planRuns(f.session.runSetup().procedure);
    const double step_s = f.session.runSetup().procedure.sample_interval_s;
    for (std::size_t r = 0; r < 2; ++r) {
        const auto& times = campaign->runs[r].samples.time_s;
        ASSERT_FALSE(times.empty());
        EXPECT_NEAR(times.back(), planned[r].duration_s, step_s);
        EXPECT_GE(double(times.size()), planned[r].duration_s / step_s - 1);
        for (std::size_t i = 1; i < times.size(); ++i)  // no hole where it was paused
            ASSERT_NEAR(times[i] - times[i - 1], step_s, 1e-9) << "run " << r << " row " << i;
    }
    // The live buffer is the last run's: its times restarted at 0.
    const auto buffer = controller.liveBuffer();
    ASSERT_TRUE(buffer);
    const auto& last = campaign->runs[1].samples.time_s;
    const live::LiveRows rows = buffer->snapshot();
    ASSERT_FALSE(rows.empty());
    EXPECT_LE(rows.time_s(0), step_s);
    EXPECT_DOUBLE_EQ(rows.time_s(rows.endRow() - 1), last.back());
    EXPECT_TRUE(page.startAction()->isEnabled());
}

TEST(RunPage, statusBarShowsTheProceduresOwnClockAfterTheRun) {
    RunFixture f(0);  // unpaced: the simulated hours pass in a moment of wall time
    ui::RunPage page(f.session);
    ui::RunController& controller = page.controller();
    QSignalSpy finished(&controller, &ui::RunController::finished);
    page.startAction()->trigger();
    ASSERT_TRUE(controller.active()) << page.checklist().problems().join(';').toStdString();
    ASSERT_TRUE(finished.wait(60000) || finished.count() == 1);
    ASSERT_TRUE(finished.first().first().toBool());
    double planned_s = 0;
    for (const auto& run : procedures::planRuns(f.session.runSetup().procedure))
        planned_s += run.duration_s;
    const double step_s = f.session.runSetup().procedure.sample_interval_s;
    EXPECT_NEAR(controller.elapsed_s(), planned_s, 2 * step_s);
    const auto* status = qobject_cast<ui::RunStatusWidget*>(page.statusWidget());
    ASSERT_TRUE(status);
    EXPECT_TRUE(status->text().contains(
        QStringLiteral("elapsed %1").arg(ui::clockText(controller.elapsed_s()))))
        << status->text().toStdString();
    EXPECT_GT(planned_s, 3600.0);  // hours of run time, so a wall clock would show far less
}

TEST(RunPage, abortMidRunKeepsTheRunMarkedInterrupted) {
    RunFixture f(200);
    ui::RunPage page(f.session);
    ui::RunController& controller = page.controller();
    QSignalSpy finished(&controller, &ui::RunController::finished);
    QSignalSpy events(&f.session, &ui::Session::event);
    page.startAction()->trigger();
    ASSERT_TRUE(QTest::qWaitFor([&] { return rowsShown(controller) > 20; }, 30000));
    ASSERT_TRUE(QTest::qWaitFor([&] { return page.abortAction()->isEnabled(); }, 5000));
    page.abortAction()->trigger();
    ASSERT_TRUE(finished.wait(30000) || finished.count() == 1);
    EXPECT_FALSE(finished.first().first().toBool());
    EXPECT_EQ(controller.state(), EngineState::Interrupted);
    EXPECT_EQ(test::runStatuses(f.store), QStringList{QStringLiteral("S1=interrupted")});
    bool told = false;
    for (const auto& e : events) told |= e.at(2).toString().contains(QStringLiteral("interrupted"));
    EXPECT_TRUE(told);
    EXPECT_TRUE(f.session.campaignId().has_value());
}

TEST(RunPage, checklistRefusesAnInvalidProcedureAndSaysWhy) {
    RunFixture f(1000);
    const QString path = f.dir.filePath(QStringLiteral("bad.json"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "driftlab.procedure/1", "name": "bad", "kind": "moving-states",
                   "travel_mm": [0, 700], "sample_interval_s": -1,
                   "moving_states": {"states": []}})");
    file.close();
    ui::RunSetup setup = f.session.runSetup();
    setup.procedure_path = path;
    f.session.setRunSetup(setup);
    ui::RunPage page(f.session);
    page.startAction()->trigger();
    EXPECT_FALSE(page.controller().active());
    ASSERT_FALSE(page.checklist().problems().isEmpty());
    const QString why = page.checklist().problems().join(';');
    EXPECT_TRUE(why.contains(QStringLiteral("not valid"))) << why.toStdString();
    EXPECT_TRUE(why.contains(QStringLiteral("sample_interval_s"))) << why.toStdString();
    EXPECT_EQ(test::runStatuses(f.store), QStringList{});
}

TEST(RunPage, checklistNamesAModbusDeviceThatDoesNotAnswerWithoutBlockingTheGui) {
    RunFixture f(0);
    quint16 freePort = 0;
    {
        QTcpServer probe;
        ASSERT_TRUE(probe.listen(QHostAddress::LocalHost, 0));
        freePort = probe.serverPort();
    }
    ui::RunSetup setup = f.session.runSetup();
    setup.rig = QStringLiteral("modbus");
    setup.temperature_url = QStringLiteral("modbus://127.0.0.1:%1").arg(freePort);
    setup.device_map_path =
        QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/devices/temperature-8ch-pt100.json");
    f.session.setRunSetup(setup);
    ui::RunPage page(f.session);
    QSignalSpy checked(&page.checklist(), &ui::PreRunChecklist::checked);
    if (page.checklist().busy()) {
        ASSERT_TRUE(checked.wait(10000));  // the check at set-up
    }
    checked.clear();
    int beats = 0;
    QTimer heartbeat;
    QObject::connect(&heartbeat, &QTimer::timeout, [&] { ++beats; });
    heartbeat.start(1);
    page.startAction()->trigger();
    // The probe runs on a worker: the action returned before the answer.
    EXPECT_TRUE(page.checklist().busy() || checked.count() == 1);
    ASSERT_TRUE(checked.count() == 1 || checked.wait(10000));
    EXPECT_FALSE(checked.first().first().toBool());
    EXPECT_FALSE(page.controller().active());
    const QString why = page.checklist().problems().join(';');
    EXPECT_TRUE(why.contains(QStringLiteral("temperature module 127.0.0.1:%1").arg(freePort)))
        << why.toStdString();
    EXPECT_GT(beats, 0);  // the GUI thread's timers ran while the device was asked
}

TEST(RunPage, abortEndsARunPausedOnALostModule) {
    if (const QString why = test::peerUnavailable(); !why.isEmpty())
        GTEST_SKIP() << why.toStdString();
    RunFixture f(0);
    // The module's loss is the point of the test, not a warning to print.
    QLoggingCategory::setFilterRules(QStringLiteral("driftlab.acquisition.devices.warning=false"));
    int port = 0;
    auto module = test::startTemperaturePeer(0, &port);
    const QString path = f.dir.filePath(QStringLiteral("etve.json"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "driftlab.procedure/1", "name": "ETVE on the bench", "kind": "etve",
                   "sample_interval_s": 0.5, "on_device_loss": "pause",
                   "etve": {"run_id": "E1", "duration_s": 600}})");
    file.close();
    QString error;
    const auto procedure = procedures::loadProcedureFile(path, &error);
    ASSERT_TRUE(procedure) << error.toStdString();
    ui::RunSetup setup = f.session.runSetup();
    setup.procedure = *procedure;
    setup.procedure_path = path;
    setup.rig = QStringLiteral("modbus");
    setup.temperature_url = QStringLiteral("modbus://127.0.0.1:%1").arg(port);
    // The peer's first channel only: its profile holds implausible values on
    // purpose, which the checklist refuses.
    QFile shipped(DRIFTLAB_SOURCE_DIR "/resources/devices/temperature-8ch-pt100.json");
    ASSERT_TRUE(shipped.open(QIODevice::ReadOnly));
    QJsonObject map = QJsonDocument::fromJson(shipped.readAll()).object();
    map[QStringLiteral("channels")] =
        QJsonArray{map.value(QStringLiteral("channels")).toArray().first()};
    setup.device_map_path = f.dir.filePath(QStringLiteral("one-channel.json"));
    QFile mapFile(setup.device_map_path);
    ASSERT_TRUE(mapFile.open(QIODevice::WriteOnly));
    mapFile.write(QJsonDocument(map).toJson());
    mapFile.close();
    f.session.setRunSetup(setup);
    ui::RunPage page(f.session);
    ui::RunController& controller = page.controller();
    QSignalSpy finished(&controller, &ui::RunController::finished);
    page.startAction()->trigger();
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return controller.active() && rowsShown(controller) > 2; }, 30000))
        << page.checklist().problems().join(';').toStdString();
    test::killPeer(*module);
    ASSERT_TRUE(QTest::qWaitFor([&] { return controller.state() == EngineState::Paused; }, 10000));
    ASSERT_TRUE(page.abortAction()->isEnabled());
    QElapsedTimer sinceAbort;
    sinceAbort.start();
    page.abortAction()->trigger();
    ASSERT_TRUE(QTest::qWaitFor([&] { return finished.count() == 1; }, 10000));
    EXPECT_LT(sinceAbort.elapsed(), 2000);
    EXPECT_EQ(controller.state(), EngineState::Interrupted);
    EXPECT_EQ(test::runStatuses(f.store), QStringList{QStringLiteral("E1=interrupted")});
}
