// Read controller and Push on the Compensation page against our simulated
// controller (real Modbus TCP on 127.0.0.1, a free port): the confirmation
// shows what changes against the active table read just before, the push is
// applied and read back, and the outcome lands in the push history; a
// controller that refuses the commit keeps its table and the refusal is shown
// and recorded.
#include <gtest/gtest.h>

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QRadioButton>
#include <QTest>

#include "acquisition/sim/SimulatedController.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/models/CompensationTableModel.h"
#include "ui/models/PushHistoryModel.h"
#include "ui/pages/CompensationPage.h"
#include "ui/shell/Session.h"
#include "ui/widgets/ControllerPanel.h"
#include "ui/widgets/PushConfirmDialog.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

struct PushFixture {
    QTemporaryDir dir;
    qint64 campaign = 0;
    ui::Session session;
    std::unique_ptr<ui::CompensationPage> page;
    std::unique_ptr<sim::SimulatedController> controller;
    ui::ControllerPanel* panel = nullptr;

    explicit PushFixture(sim::ControllerFaults faults = {}) {
        sim::SimulatedControllerOptions options;
        options.faults = faults;
        controller = std::make_unique<sim::SimulatedController>(options);
        QString error;
        EXPECT_TRUE(controller->start(&error)) << qPrintable(error);
        EXPECT_TRUE(session.openStore(importExample(dir, &campaign), false, &error))
            << qPrintable(error);
        page = std::make_unique<ui::CompensationPage>(session);
        QSignalSpy updated(page.get(), &ui::CompensationPage::tableUpdated);
        session.selectCampaign(campaign);
        EXPECT_TRUE(waitFor(updated));
        QTest::mouseClick(page->spacingButton(), Qt::LeftButton);
        page->spacingBox()->setValue(35);
        panel = page->controllerPanel();
        panel->urlEdit()->setText(controller->url());
    }

    /// Push… → the confirmation (after the active table was read) → its summary.
    QString openConfirmation() {
        QSignalSpy read(panel, &ui::ControllerPanel::activeTableRead);
        QTest::mouseClick(panel->pushButton(), Qt::LeftButton);
        EXPECT_TRUE(waitFor(read)) << qPrintable(panel->statusLabel()->text());
        EXPECT_NE(panel->confirmation(), nullptr);
        return panel->confirmation() ? panel->confirmation()->summary() : QString();
    }

    /// Clicks "Push" in the confirmation and waits for the outcome.
    push::PushResult confirm() {
        QSignalSpy finished(panel, &ui::ControllerPanel::pushFinished);
        QPushButton* accept = panel->confirmation()->pushButton();
        QTest::mouseClick(accept, Qt::LeftButton);
        EXPECT_TRUE(waitFor(finished)) << qPrintable(panel->statusLabel()->text());
        return finished.isEmpty() ? push::PushResult{}
                                  : finished.front().front().value<push::PushResult>();
    }
};

QString historyResult(ui::PushHistoryModel* m, int row) {
    return m->data(m->index(row, ui::PushHistoryModel::Result)).toString();
}

}  // namespace

TEST(CompensationPush, readControllerShowsTheDifferenceToItsActiveTable) {
    PushFixture f;
    ASSERT_EQ(f.page->tableModel()->columnCount(), 4);  // position, +, −, uncertainty
    QSignalSpy read(f.panel, &ui::ControllerPanel::activeTableRead);
    QTest::mouseClick(f.panel->readButton(), Qt::LeftButton);
    ASSERT_TRUE(waitFor(read)) << qPrintable(f.panel->statusLabel()->text());
    // A fresh controller holds no table: the change is the whole correction.
    ui::CompensationTableModel* m = f.page->tableModel();
    ASSERT_EQ(m->columnCount(), 8);
    for (int row = 0; row < m->rowCount(); ++row)
        EXPECT_EQ(m->data(m->index(row, ui::CompensationTableModel::ChangePlus)).toString(),
                  m->data(m->index(row, ui::CompensationTableModel::CorrectionPlus)).toString());
    EXPECT_TRUE(f.panel->statusLabel()->text().contains(QStringLiteral("no table")));
    EXPECT_EQ(f.controller->writeRequests(), 0);  // reading writes nothing
}

TEST(CompensationPush, confirmedPushIsAppliedReadBackAndRecorded) {
    PushFixture f;
    const QString summary = f.openConfirmation();
    EXPECT_TRUE(summary.contains(QStringLiteral("holds no table"))) << qPrintable(summary);
    EXPECT_TRUE(summary.contains(QStringLiteral("21 of 21 points change"))) << qPrintable(summary);
    const push::PushResult result = f.confirm();
    EXPECT_EQ(result.outcome, push::PushOutcome::Applied) << qPrintable(result.message);
    EXPECT_EQ(f.controller->applied(), 1);
    EXPECT_EQ(f.controller->activeTable().points(), 21);
    EXPECT_TRUE(f.panel->statusLabel()->text().contains(QStringLiteral("applied")));
    EXPECT_GE(f.panel->stepList()->count(), 9);  // connect … read_back, one line each
    ui::PushHistoryModel* history = f.panel->historyModel();
    ASSERT_EQ(history->rowCount(), 1);
    EXPECT_EQ(historyResult(history, 0), QStringLiteral("applied"));
    EXPECT_EQ(history->data(history->index(0, ui::PushHistoryModel::Run)).toString(),
              QStringLiteral("S1"));

    // The same table again: the confirmation says nothing changes.
    const QString again = f.openConfirmation();
    EXPECT_TRUE(again.contains(QStringLiteral("holds table v1"))) << qPrintable(again);
    EXPECT_TRUE(again.contains(QStringLiteral("0 of 21 points change"))) << qPrintable(again);
    f.panel->confirmation()->reject();
    EXPECT_EQ(f.controller->applied(), 1);
}

TEST(CompensationPush, aControllerThatRefusesKeepsItsTableAndTheRefusalIsShownAndRecorded) {
    sim::ControllerFaults faults;
    faults.refuse_commit = true;
    PushFixture f(faults);
    f.openConfirmation();
    const push::PushResult result = f.confirm();
    EXPECT_EQ(result.outcome, push::PushOutcome::Refused) << qPrintable(result.message);
    EXPECT_EQ(f.controller->applied(), 0);
    EXPECT_EQ(f.controller->activeTable().version(), 0);  // nothing half-applied
    EXPECT_TRUE(f.panel->statusLabel()->text().contains(QStringLiteral("refused")))
        << qPrintable(f.panel->statusLabel()->text());
    ASSERT_EQ(f.panel->historyModel()->rowCount(), 1);
    EXPECT_EQ(historyResult(f.panel->historyModel(), 0), QStringLiteral("refused"));
}

TEST(CompensationPush, aBadControllerAddressIsNamedAndNothingIsSent) {
    PushFixture f;
    f.panel->urlEdit()->setText(QStringLiteral("http://nowhere"));
    QTest::mouseClick(f.panel->readButton(), Qt::LeftButton);
    EXPECT_TRUE(f.panel->statusLabel()->text().contains(QStringLiteral("Controller address")))
        << qPrintable(f.panel->statusLabel()->text());
    EXPECT_EQ(f.panel->confirmation(), nullptr);
    EXPECT_TRUE(f.panel->readButton()->isEnabled());
}
