// The device health model: a light per device from its events, checked by
// QAbstractItemModelTester while it changes.
#include <gtest/gtest.h>

#include <QAbstractItemModelTester>

#include "ui/models/DeviceHealthModel.h"

using namespace driftlab;
using ui::DeviceHealth;

TEST(DeviceHealthModel, errorMakesADeviceLostAndItsGapBringsItBack) {
    ui::DeviceHealthModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.reset({QStringLiteral("temperature module 10.0.0.5:502"),
                 QStringLiteral("controller 10.0.0.6:502")});
    ASSERT_EQ(model.rowCount(), 2);
    EXPECT_EQ(model.health(0), DeviceHealth::Ok);
    model.report(QStringLiteral("error"), QStringLiteral("temperature module 10.0.0.5:502"),
                 QStringLiteral("connection refused"));
    EXPECT_EQ(model.health(0), DeviceHealth::Lost);
    EXPECT_EQ(model.health(1), DeviceHealth::Ok);
    EXPECT_EQ(model.data(model.index(0, ui::DeviceHealthModel::MessageColumn), Qt::DisplayRole)
                  .toString(),
              QStringLiteral("connection refused"));
    model.report(QStringLiteral("warning"), QStringLiteral("temperature module 10.0.0.5:502"),
                 QStringLiteral("gap: no data from a to b (3 s); reconnected"));
    EXPECT_EQ(model.health(0), DeviceHealth::Ok);
    model.report(QStringLiteral("warning"), QStringLiteral("controller 10.0.0.6:502"),
                 QStringLiteral("slow answer"));
    EXPECT_EQ(model.health(1), DeviceHealth::Warning);
}

TEST(DeviceHealthModel, anUnknownDeviceIsAddedButEngineNotesAreNot) {
    ui::DeviceHealthModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
    model.reset({QStringLiteral("simulated rig")});
    model.report(QStringLiteral("info"), QStringLiteral("engine"), QStringLiteral("end warm-up"));
    EXPECT_EQ(model.rowCount(), 1);
    model.report(QStringLiteral("error"), QStringLiteral("interferometer 127.0.0.1:5000"),
                 QStringLiteral("stream ended"));
    ASSERT_EQ(model.rowCount(), 2);
    EXPECT_EQ(model.health(1), DeviceHealth::Lost);
    EXPECT_EQ(model.data(model.index(1, 0), Qt::DecorationRole).value<QColor>(),
              ui::DeviceHealthModel::colourOf(DeviceHealth::Lost));
}
