// The item models of the Compensation and ISO 230-2 pages under
// QAbstractItemModelTester (fatal on any breach of the model contract), through
// every change the pages make: set, add the active table, clear.
#include <gtest/gtest.h>

#include <QAbstractItemModelTester>

#include "core/compensation/CompensationTable.h"
#include "core/iso/Iso230_2.h"
#include "tests/ui/UiTestSupport.h"
#include "ui/models/CompensationTableModel.h"
#include "ui/models/Iso230_2TargetModel.h"
#include "ui/models/PushHistoryModel.h"

using namespace driftlab;
using Tester = QAbstractItemModelTester;

namespace {

iso::Evaluation fiveTargets() {
    std::vector<iso::Reading> readings;
    for (int cycle = 1; cycle <= 5; ++cycle)
        for (int i = 0; i < 5; ++i) {
            const double target = 100.0 * i;
            readings.push_back({target, Direction::Positive, cycle, 2.0 * i + 0.1 * cycle});
            readings.push_back({target, Direction::Negative, cycle, 2.0 * i - 3 + 0.2 * cycle});
        }
    return iso::evaluate(readings);
}

}  // namespace

TEST(UiModels, compensationTableModelKeepsTheContractThroughSetActiveAndClear) {
    ui::CompensationTableModel model;
    Tester tester(&model, Tester::FailureReportingMode::Fatal);
    compensation::TableSettings settings;
    settings.bidirectional = true;
    const compensation::TableResult built = compensation::buildTable(fiveTargets(), settings);
    ASSERT_TRUE(built.ok()) << qPrintable(built.error);
    model.setTable(built.table);
    EXPECT_EQ(model.rowCount(), 5);
    EXPECT_EQ(model.columnCount(), 4);  // position, +, −, uncertainty
    EXPECT_DOUBLE_EQ(
        model.data(model.index(2, ui::CompensationTableModel::Uncertainty), Qt::UserRole)
            .toDouble(),
        built.table.uncertainty_um[2]);
    model.setActive(push::TableImage{});  // a controller without a table
    EXPECT_EQ(model.columnCount(), 8);
    // Against "no table" every correction is a change.
    EXPECT_EQ(model.change()->points_changed, 5);
    EXPECT_DOUBLE_EQ(
        model.data(model.index(4, ui::CompensationTableModel::ChangePlus), Qt::UserRole).toDouble(),
        built.table.correction_plus_um[4]);
    model.setTable(built.table);  // rebuilt: the active table stays
    EXPECT_EQ(model.columnCount(), 8);
    model.clear();
    EXPECT_EQ(model.rowCount(), 0);
    EXPECT_EQ(model.columnCount(), 4);
}

TEST(UiModels, iso230_2TargetModelShowsNotDeterminedAsNa) {
    ui::Iso230_2TargetModel model;
    Tester tester(&model, Tester::FailureReportingMode::Fatal);
    const iso::Evaluation e = fiveTargets();
    model.setTargets(e.targets);
    EXPECT_EQ(model.rowCount(), 5);
    EXPECT_EQ(model.data(model.index(2, ui::Iso230_2TargetModel::MeanUp)).toString(),
              QString::number(e.targets[2].mean_up_um, 'f', 3));
    std::vector<iso::TargetResult> oneWay = e.targets;
    oneWay[0].mean_down_um = iso::kNotDetermined;
    model.setTargets(oneWay);
    EXPECT_EQ(model.data(model.index(0, ui::Iso230_2TargetModel::MeanDown)).toString(),
              QStringLiteral("n/a"));
    model.setTargets({});
    EXPECT_EQ(model.rowCount(), 0);
}

TEST(UiModels, pushHistoryModelShowsTheNewestPushFirst) {
    ui::PushHistoryModel model;
    Tester tester(&model, Tester::FailureReportingMode::Fatal);
    db::PushRecord first, second;
    first.result = QStringLiteral("applied");
    first.table_version = 1;
    second.result = QStringLiteral("refused");
    second.table_version = 2;
    model.setPushes({first, second});
    ASSERT_EQ(model.rowCount(), 2);
    EXPECT_EQ(model.data(model.index(0, ui::PushHistoryModel::Result)).toString(),
              QStringLiteral("refused"));
    EXPECT_EQ(model.data(model.index(1, ui::PushHistoryModel::Version)).toInt(), 1);
    model.setPushes({});
    EXPECT_EQ(model.rowCount(), 0);
}
