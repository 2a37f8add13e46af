// The Set-up page through its widgets: each bad field is named beside it and
// in the summary, a valid set-up applies to the session, the machine set-up
// survives a campaign.json round trip, and the demo is a valid set-up.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QGroupBox>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "core/bundle/CampaignJson.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/models/ChannelSetupModel.h"
#include "ui/pages/SetupPage.h"
#include "ui/shell/Session.h"
#include "ui/widgets/MachineForm.h"
#include "ui/widgets/ProcedureForm.h"
#include "ui/widgets/RigForm.h"
#include "ui/widgets/ScrewForm.h"

namespace driftlab::ui {
namespace {

struct SetupPageTest : ::testing::Test {
    Session session;
    SetupPage page{session};
    void SetUp() override { page.loadDemo(); }
    QPushButton* applyButton() {
        return page.findChild<QPushButton*>(QStringLiteral("ApplySetup"));
    }
};

TEST_F(SetupPageTest, theDemoIsAValidSetupOfTheSimulatedRigAppliedToTheSession) {
    EXPECT_TRUE(page.validate().isEmpty()) << qPrintable(page.validate().join('\n'));
    EXPECT_TRUE(page.demoBannerShown());
    const RunSetup& setup = session.runSetup();
    EXPECT_EQ(setup.rig, QStringLiteral("sim"));
    EXPECT_EQ(setup.speedup, 600);
    ASSERT_TRUE(setup.procedure.moving_states);
    ASSERT_EQ(setup.procedure.moving_states->states.size(), 2u);
    EXPECT_EQ(setup.procedure.moving_states->states[0].run_id, QStringLiteral("S1"));
    EXPECT_EQ(setup.procedure.moving_states->states[1].run_id, QStringLiteral("S4"));
    EXPECT_LT(setup.procedure.moving_states->states[0].warmup_s, 7200);
    // The story's hidden effect, as the rig takes it (`simulate --effect ID=VALUE`).
    ASSERT_EQ(setup.effects.size(), 1);
    EXPECT_TRUE(setup.effects[0].startsWith(SetupPage::demoHiddenCause() + QLatin1Char('=')))
        << setup.effects[0].toStdString();
    ASSERT_TRUE(setup.machine);
    EXPECT_TRUE(setup.machine->findChannel(QStringLiteral("T_nut")));
    EXPECT_EQ(setup.machine->findChannel(QStringLiteral("T_nut"))->role, ChannelRole::Nut);
}

TEST_F(SetupPageTest, eachBadFieldIsNamedBesideItAndInTheSummaryAndNothingIsApplied) {
    QSignalSpy applied(&session, &Session::runSetupChanged);
    ScrewForm* screw = page.screwForm();
    screw->lead_mm->setValue(0);
    page.machineForm()->machineName->clear();
    page.machineForm()->travelTo_mm->setValue(-5);
    page.channelModel()->setChannels(
        {test::channel("T_nut", Quantity::Temperature, ChannelRole::Nut),
         test::channel("T_bed", Quantity::Temperature, ChannelRole::Structure),
         test::channel("T_x", Quantity::Temperature, ChannelRole::DriftX)});
    page.rigForm()->speedup->setValue(0);
    page.procedureForm()->keyBoxes.front()->setValue(0);  // the sample interval

    QTest::mouseClick(applyButton(), Qt::LeftButton);
    EXPECT_EQ(applied.count(), 0);
    const QStringList problems = page.validate();
    const QString all = problems.join('\n');
    EXPECT_TRUE(problems.contains(QStringLiteral("Screw → lead: must be > 0 mm")))
        << qPrintable(all);
    EXPECT_EQ(screw->errors().errorOf(screw->lead_mm), QStringLiteral("must be > 0 mm"));
    EXPECT_TRUE(problems.contains(QStringLiteral("Machine → machine name: must not be empty")));
    EXPECT_TRUE(all.contains(QStringLiteral("Travel → to: must be greater than from")));
    EXPECT_TRUE(problems.contains(
        QStringLiteral("Channels row 3 (T_x): role 'drift_x' does not fit a temperature")));
    EXPECT_TRUE(problems.contains(QStringLiteral("Rig → speed-up: must be > 0")));
    EXPECT_TRUE(all.contains(QStringLiteral("Procedure → procedure.sample_interval_s")))
        << qPrintable(all);
    EXPECT_EQ(page.rigForm()->errors().errorOf(page.rigForm()->speedup),
              QStringLiteral("must be > 0"));
}

TEST_F(SetupPageTest, aProcedureEditedIntoAnErrorNamesTheKeyPath) {
    QString text = page.procedureForm()->json->toPlainText();
    text.replace(QStringLiteral("\"targets\": 11"), QStringLiteral("\"targets\": \"11\""));
    page.procedureForm()->json->setPlainText(text);
    EXPECT_FALSE(page.procedureForm()->procedure());
    EXPECT_TRUE(
        page.procedureForm()->error().startsWith(QStringLiteral("procedure.moving_states.targets")))
        << qPrintable(page.procedureForm()->error());
    EXPECT_FALSE(page.apply());
}

TEST_F(SetupPageTest, theModbusRigNeedsItsUrlsAndChannelIdsFromTheDeviceMap) {
    page.rigForm()->setSimulated(false);
    page.rigForm()->temperatureUrl->setText(QStringLiteral("modbus//nowhere"));
    page.rigForm()->interferometerUrl->setText(QStringLiteral("udp://host:1"));
    const QStringList problems = page.validate();
    const QString all = problems.join('\n');
    EXPECT_TRUE(all.contains(QStringLiteral("Rig → temperature module URL: "))) << qPrintable(all);
    EXPECT_TRUE(all.contains(QStringLiteral("Rig → interferometer URL: 'udp://host:1' is not")));
    EXPECT_TRUE(all.contains(QStringLiteral(
        "Channels row 1 (T_nut): 'T_nut' is not a channel of the device map temperature-8ch")));

    // The module's ids with roles, and a real address: the set-up applies.
    page.channelModel()->setChannels(
        {test::channel("T1", Quantity::Temperature, ChannelRole::Nut),
         test::channel("T2", Quantity::Temperature, ChannelRole::Ambient)});
    page.rigForm()->temperatureUrl->setText(QStringLiteral("modbus://127.0.0.1:1502"));
    page.rigForm()->interferometerUrl->clear();
    ASSERT_TRUE(page.apply()) << qPrintable(page.validate().join('\n'));
    EXPECT_EQ(session.runSetup().rig, QStringLiteral("modbus"));
    EXPECT_EQ(session.runSetup().temperature_url, QStringLiteral("modbus://127.0.0.1:1502"));
    EXPECT_EQ(session.runSetup().machine->channels.size(), 2u);
    EXPECT_FALSE(page.demoBannerShown());
}

TEST_F(SetupPageTest, aValidChangeAppliesAndTheSessionHasIt) {
    QSignalSpy applied(&session, &Session::runSetupChanged);
    page.screwForm()->lead_mm->setValue(16);
    page.rigForm()->seed->setValue(7);
    QTest::mouseClick(applyButton(), Qt::LeftButton);
    ASSERT_EQ(applied.count(), 1);
    EXPECT_EQ(session.runSetup().seed, 7u);
    EXPECT_DOUBLE_EQ(session.runSetup().machine->screw->lead_mm, 16);
}

TEST_F(SetupPageTest, theMachineSetupRoundTripsThroughCampaignJson) {
    page.machineForm()->controller->setText(QStringLiteral("LinuxCNC 2.9"));
    page.screwForm()->mounting->setCurrentText(QStringLiteral("fixed-fixed"));
    page.machineForm()->environmentCompensation->setChecked(false);
    const Campaign before = page.machine();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("campaign.json"));
    QString error;
    ASSERT_TRUE(page.saveMachine(path, &error)) << qPrintable(error);

    // What `driftlab-cli run --machine` reads: the same parser.
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const Campaign parsed = bundle::campaignFromJson(file.readAll(), path);
    EXPECT_TRUE(parsed.runs.empty());
    EXPECT_EQ(parsed.machine.controller, QStringLiteral("LinuxCNC 2.9"));

    Session other;
    SetupPage fresh(other);
    ASSERT_TRUE(fresh.loadMachine(path, &error)) << qPrintable(error);
    EXPECT_EQ(fresh.machine(), before);
    EXPECT_EQ(fresh.screwForm()->mounting->currentText(), QStringLiteral("fixed-fixed"));
    EXPECT_FALSE(fresh.machineForm()->environmentCompensation->isChecked());
}

TEST_F(SetupPageTest, aBrokenMachineFileIsRefusedNamingTheFileAndKey) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("campaign.json"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "driftlab.campaign/1", "name": "x", "machine": {"name": 5}})");
    file.close();
    const Campaign before = page.machine();
    QString error;
    EXPECT_FALSE(page.loadMachine(path, &error));
    EXPECT_TRUE(error.startsWith(path)) << qPrintable(error);
    EXPECT_EQ(page.machine(), before);
}

TEST_F(SetupPageTest, everyShippedProcedureLoadsAndShowsItsKeyNumbers) {
    for (const QString& path : ProcedureForm::shippedProcedures()) {
        QString error;
        ASSERT_TRUE(page.procedureForm()->loadFile(path, &error)) << qPrintable(error);
        EXPECT_TRUE(page.procedureForm()->error().isEmpty()) << qPrintable(path);
        EXPECT_FALSE(page.procedureForm()->keyBoxes.empty());
    }
    EXPECT_EQ(ProcedureForm::shippedProcedures().size(), 6);
}

}  // namespace
}  // namespace driftlab::ui
