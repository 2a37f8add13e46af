// Every item model of the set-up and the docks, checked by
// QAbstractItemModelTester (fatal) while it is filled and edited.
#include <gtest/gtest.h>

#include <QAbstractItemModelTester>
#include <QTemporaryDir>

#include "db/CampaignStore.h"
#include "db/StoreOverview.h"
#include "tests/support/CliRunner.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/models/CampaignTreeModel.h"
#include "ui/models/ChannelSetupModel.h"
#include "ui/models/EventLogModel.h"

namespace driftlab::ui {
namespace {

using Tester = QAbstractItemModelTester;

std::vector<Channel> someChannels() {
    return {
        {QStringLiteral("T_nut"),
         Quantity::Temperature,
         ChannelRole::Nut,
         QStringLiteral("nut"),
         350.0,
         {}},
        {QStringLiteral("T_air"), Quantity::Temperature, ChannelRole::Air, {}, std::nullopt, {}},
        {QStringLiteral("D_x"), Quantity::Displacement, ChannelRole::DriftX, {}, std::nullopt, {}}};
}

TEST(ChannelSetupModel, staysConsistentWhileEditedAndRefusesARoleThatDoesNotFit) {
    ChannelSetupModel model;
    Tester tester(&model, Tester::FailureReportingMode::Fatal);
    model.setChannels(someChannels());
    ASSERT_EQ(model.rowCount(), 3);

    const QModelIndex role = model.index(0, ChannelSetupModel::RoleColumn);
    EXPECT_FALSE(model.setData(role, QStringLiteral("drift_x")));
    EXPECT_EQ(model.channels()[0].role, ChannelRole::Nut);
    EXPECT_TRUE(model.setData(role, QStringLiteral("bearing")));
    EXPECT_EQ(model.channels()[0].role, ChannelRole::Bearing);
    EXPECT_EQ(model.data(role, ChannelSetupModel::ChoicesRole).toStringList(),
              roleNamesFor(Quantity::Temperature));

    // A new quantity resets a role that no longer fits.
    EXPECT_TRUE(
        model.setData(model.index(1, ChannelSetupModel::QuantityColumn), QStringLiteral("speed")));
    EXPECT_EQ(model.channels()[1].role, ChannelRole::Spindle);
    EXPECT_FALSE(
        model.setData(model.index(1, ChannelSetupModel::QuantityColumn), QStringLiteral("heat")));

    EXPECT_TRUE(
        model.setData(model.index(2, ChannelSetupModel::PositionColumn), QStringLiteral("")));
    EXPECT_FALSE(model.channels()[2].position_mm.has_value());
    EXPECT_FALSE(
        model.setData(model.index(2, ChannelSetupModel::PositionColumn), QStringLiteral("far")));
    EXPECT_FALSE(model.flags(model.index(0, ChannelSetupModel::DeviceColumn)) & Qt::ItemIsEditable);

    ASSERT_TRUE(model.insertRows(1, 2));
    EXPECT_EQ(model.rowCount(), 5);
    ASSERT_TRUE(model.removeRows(0, 3));
    EXPECT_EQ(model.rowCount(), 2);
    EXPECT_FALSE(model.removeRows(1, 5));
}

TEST(ChannelSetupModel, namesTheRowAndChannelOfEveryProblem) {
    ChannelSetupModel model;
    Tester tester(&model, Tester::FailureReportingMode::Fatal);
    auto channels = someChannels();
    channels[2].quantity = Quantity::Temperature;  // a file may say anything: flagged, not hidden
    channels[1].id = QStringLiteral("T_nut");
    channels.push_back(test::channel("bad id", Quantity::Temperature, ChannelRole::Other));
    model.setChannels(channels);
    const QStringList problems = model.problems(false);
    EXPECT_TRUE(problems.contains(
        QStringLiteral("Channels row 3 (D_x): role 'drift_x' does not fit a temperature")))
        << qPrintable(problems.join('\n'));
    EXPECT_TRUE(
        problems.contains(QStringLiteral("Channels row 2 (T_nut): id is used by row 1 too")));
    EXPECT_TRUE(problems.contains(
        QStringLiteral("Channels row 4 (bad id): id must be letters, digits and _ only")));
    EXPECT_EQ(problems.size(), 3);
}

TEST(ChannelSetupModel, showsAndChecksTheDeviceChannelOfEachId) {
    ChannelSetupModel model;
    Tester tester(&model, Tester::FailureReportingMode::Fatal);
    QString error;
    const auto map = devices::loadChannelRegisterMap(
        QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/devices/temperature-8ch-pt100.json"),
        &error);
    ASSERT_TRUE(map) << qPrintable(error);
    model.setChannels({test::channel("T3", Quantity::Temperature, ChannelRole::Nut),
                       test::channel("T_nut", Quantity::Temperature, ChannelRole::Bearing)});
    model.setDeviceMap(map);
    EXPECT_TRUE(model.index(0, ChannelSetupModel::DeviceColumn)
                    .data()
                    .toString()
                    .startsWith(QStringLiteral("input register 2")))
        << qPrintable(model.index(0, ChannelSetupModel::DeviceColumn).data().toString());
    const QStringList problems = model.problems(true);
    ASSERT_EQ(problems.size(), 1);
    EXPECT_TRUE(
        problems[0].startsWith(QStringLiteral("Channels row 2 (T_nut): 'T_nut' is not a channel of "
                                              "the device map temperature-8ch-pt100")))
        << qPrintable(problems[0]);
    EXPECT_TRUE(model.problems(false).isEmpty());
}

TEST(EventLogModel, keepsTheNewestRowsUpToItsCapacity) {
    EventLogModel model(3);
    Tester tester(&model, Tester::FailureReportingMode::Fatal);
    for (int i = 1; i <= 5; ++i)
        model.append(QStringLiteral("info"), QStringLiteral("test"),
                     QStringLiteral("event %1").arg(i));
    ASSERT_EQ(model.rowCount(), 3);
    EXPECT_EQ(model.index(0, 3).data().toString(), QStringLiteral("event 3"));
    EXPECT_EQ(model.index(2, 3).data().toString(), QStringLiteral("event 5"));
    EXPECT_EQ(model.columnCount(), 4);
}

TEST(CampaignTreeModel, showsTheCampaignsRunsAndFitsOfAStoreMadeWithTheCli) {
    QTemporaryDir dir;
    const QString dbPath = dir.filePath(QStringLiteral("store.sqlite"));
    const test::CliResult imported =
        test::runCli({QStringLiteral("import"), test::simulatedCampaign(QStringLiteral("S1,S4"), 3),
                      QStringLiteral("--db"), dbPath});
    ASSERT_EQ(imported.exitCode, 0) << imported.err.constData();
    const QString id = QString::fromUtf8(imported.out.trimmed());
    const test::CliResult fit = test::runCli(
        {QStringLiteral("fit"), QStringLiteral("--db"), dbPath, QStringLiteral("--campaign"), id,
         QStringLiteral("--model"), QStringLiteral("mlr"), QStringLiteral("--train"),
         QStringLiteral("S1"), QStringLiteral("--test"), QStringLiteral("S4")});
    ASSERT_EQ(fit.exitCode, 0) << fit.err.constData();

    QString error;
    auto store = db::CampaignStore::open(dbPath, db::StoreAccess::ReadOnly, &error);
    ASSERT_TRUE(store) << qPrintable(error);
    const auto overview = db::storeOverview(*store, &error);
    ASSERT_TRUE(overview) << qPrintable(error);

    CampaignTreeModel model;
    Tester tester(&model, Tester::FailureReportingMode::Fatal);
    model.setOverview(*overview);
    ASSERT_EQ(model.rowCount(), 1);
    const QModelIndex campaign = model.campaignIndex(id.toLongLong());
    ASSERT_TRUE(campaign.isValid());
    QStringList kinds, names;
    for (int r = 0; r < model.rowCount(campaign); ++r) {
        const QModelIndex child = model.index(r, 0, campaign);
        kinds << QString::number(child.data(CampaignTreeModel::KindRole).toInt());
        names << child.data().toString();
        EXPECT_EQ(child.data(CampaignTreeModel::CampaignIdRole).toLongLong(), id.toLongLong());
    }
    EXPECT_EQ(kinds.count(QString::number(int(CampaignTreeModel::ItemKind::Run))), 2)
        << qPrintable(names.join(", "));
    EXPECT_EQ(kinds.count(QString::number(int(CampaignTreeModel::ItemKind::Fit))), 1)
        << qPrintable(names.join(", "));
    model.setOverview({});  // a store closed: the tester checks the reset
    EXPECT_EQ(model.rowCount(), 0);
}

}  // namespace
}  // namespace driftlab::ui
