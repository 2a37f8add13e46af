// The controller link: the axis state of block 0 (docs/modbus-register-map.md,
// registers 8…13) read from DriftLab's simulated controller and from the
// independent pymodbus controller; scale and sign pinned by hand-computed
// register words; the polled device against a peer killed mid-run.
#include <gtest/gtest.h>

#include <QSignalSpy>

#include "acquisition/devices/ControllerLink.h"
#include "acquisition/sim/SimulatedController.h"
#include "tests/acquisition/DevicePeer.h"
#include "tests/support/SignalWait.h"

using namespace driftlab;
using namespace driftlab::devices;

namespace {

std::optional<ControllerReading> readOnce(int port, QString* error) {
    ControllerLink link(test::localPeer(port));
    if (!link.connect(error)) return std::nullopt;
    auto reading = link.read(error);
    EXPECT_EQ(link.requests(), 1);  // registers 0…13 in one request
    return reading;
}

}  // namespace

TEST(AxisStateRegisters, scaleSignAndWordOrderPinnedByHandComputedWords) {
    // −123.4567 mm = −1234567 × 0.1 µm = 0xFFED2979; −8000.5 mm/min = −80005
    // × 0.1 = 0xFFFEC77B; 12.34 N·m = 1234 × 0.01 = 0x04D2. High word first.
    const AxisStateWords words = encodeAxisState({-123.4567, -8000.5, 12.34});
    const AxisStateWords expected = {0xFFED, 0x2979, 0xFFFE, 0xC77B, 0x04D2};
    EXPECT_EQ(words, expected);
    const AxisState back = decodeAxisState(std::span<const std::uint16_t, 5>(expected));
    EXPECT_DOUBLE_EQ(back.position_mm, -123.4567);
    EXPECT_DOUBLE_EQ(back.feed_mm_min, -8000.5);
    EXPECT_DOUBLE_EQ(back.torque_Nm, 12.34);
    // 350 mm = 3 500 000 = 0x003567E0; −2.5 N·m = −250 = 0xFF06.
    const AxisStateWords positive = encodeAxisState({350.0, 12000.0, -2.5});
    EXPECT_EQ(positive, (AxisStateWords{0x0035, 0x67E0, 0x0001, 0xD4C0, 0xFF06}));
}

TEST(AxisStateRegisters, roundsHalvesAwayFromZeroAndSaturates) {
    EXPECT_EQ(encodeAxisState({0.00005, 0.05, 0.005})[1], 1);
    EXPECT_EQ(encodeAxisState({-0.00005, 0, 0})[1], 0xFFFF);
    EXPECT_EQ(encodeAxisState({0, 0, -0.005})[4], 0xFFFF);
    // 500 N·m is beyond int16 in 0.01 N·m: the register holds 327.67.
    EXPECT_EQ(encodeAxisState({0, 0, 500})[4], 0x7FFF);
    EXPECT_EQ(encodeAxisState({0, 0, -500})[4], 0x8000);
    EXPECT_EQ(encodeAxisState({1e9, 0, 0})[0], 0x7FFF);
}

TEST(ControllerLinkSim, axisStateSetOnTheSimulatedControllerIsReadBack) {
    sim::SimulatedController controller;
    QString error;
    ASSERT_TRUE(controller.start(&error)) << qPrintable(error);
    controller.setAxisState({-123.4567, -8000.5, 12.34});
    controller.setMachineState(MachineState::Cutting);
    // The registers as the map documents them, independent of the decoder.
    EXPECT_EQ(controller.registerValue(8), 1);
    EXPECT_EQ(controller.registerValue(9), 0xFFED);
    EXPECT_EQ(controller.registerValue(10), 0x2979);
    EXPECT_EQ(controller.registerValue(11), 0xFFFE);
    EXPECT_EQ(controller.registerValue(12), 0xC77B);
    EXPECT_EQ(controller.registerValue(13), 0x04D2);

    auto reading = readOnce(controller.port(), &error);
    ASSERT_TRUE(reading) << qPrintable(error);
    EXPECT_DOUBLE_EQ(reading->position_mm, -123.4567);
    EXPECT_DOUBLE_EQ(reading->feed_mm_min, -8000.5);
    EXPECT_DOUBLE_EQ(reading->torque_Nm, 12.34);
    EXPECT_EQ(reading->state, MachineState::Cutting);
    EXPECT_TRUE(reading->time_utc.isValid());

    // Every state by its name, and a new axis state on the same controller.
    const std::pair<MachineState, const char*> states[] = {
        {MachineState::Idle, "idle"},
        {MachineState::Moving, "moving"},
        {MachineState::Cutting, "cutting"},
        {MachineState::ToolChange, "tool change"}};
    for (const auto& [state, name] : states) {
        controller.setMachineState(state);
        controller.setAxisState({700.0, 0.0, -0.01});
        reading = readOnce(controller.port(), &error);
        ASSERT_TRUE(reading) << qPrintable(error);
        EXPECT_EQ(machineStateName(reading->state), QLatin1String(name));
        EXPECT_DOUBLE_EQ(reading->position_mm, 700.0);
        EXPECT_DOUBLE_EQ(reading->torque_Nm, -0.01);
    }
}

TEST(ControllerLinkSim, aDeviceThatIsNotTheMapIsRefusedNamingTheRegisters) {
    if (const QString why = test::peerUnavailable(); !why.isEmpty())
        GTEST_SKIP() << qPrintable(why);
    // The temperature module's holding register 0 is 0, not the magic 0x4446.
    int port = 0;
    auto peer = test::startTemperaturePeer(0, &port);
    ASSERT_GT(port, 0);
    ControllerLink link(test::localPeer(port));
    QString error;
    ASSERT_TRUE(link.connect(&error)) << qPrintable(error);
    EXPECT_FALSE(link.read(&error));
    EXPECT_TRUE(error.contains(QStringLiteral("not DriftLab's register map"))) << qPrintable(error);
    EXPECT_TRUE(error.contains(QStringLiteral("0x0000"))) << qPrintable(error);
    EXPECT_FALSE(link.isConnected());
    test::killPeer(*peer);
}

TEST(ControllerLinkPeer, axisStateOfTheIndependentControllerIsReadWithScaleAndSign) {
    if (const QString why = test::peerUnavailable(); !why.isEmpty())
        GTEST_SKIP() << qPrintable(why);
    int port = 0;
    auto peer = test::startControllerPeer(
        0, &port,
        {QStringLiteral("--position-mm=-123.4567"), QStringLiteral("--feed-mm-min=-8000.5"),
         QStringLiteral("--torque-nm=12.34"), QStringLiteral("--state=tool-change")});
    ASSERT_GT(port, 0);
    QString error;
    const auto reading = readOnce(port, &error);
    ASSERT_TRUE(reading) << qPrintable(error);
    EXPECT_DOUBLE_EQ(reading->position_mm, -123.4567);
    EXPECT_DOUBLE_EQ(reading->feed_mm_min, -8000.5);
    EXPECT_DOUBLE_EQ(reading->torque_Nm, 12.34);
    EXPECT_EQ(reading->state, MachineState::ToolChange);
    test::killPeer(*peer);
}

TEST(ControllerDevice, peerKilledMidRun_oneErrorAGapAndReconnect) {
    if (const QString why = test::peerUnavailable(); !why.isEmpty())
        GTEST_SKIP() << qPrintable(why);
    const QStringList axis{QStringLiteral("--position-mm=250.5"),
                           QStringLiteral("--feed-mm-min=6000"), QStringLiteral("--torque-nm=3.2"),
                           QStringLiteral("--state=moving")};
    int port = 0;
    auto peer = test::startControllerPeer(0, &port, axis);
    ASSERT_GT(port, 0);
    DeviceWorkerOptions options;
    options.poll_interval_s = 0.05;
    options.backoff_initial_s = 0.05;
    options.backoff_max_s = 0.4;
    ControllerDevice device(test::localPeer(port), options);
    QSignalSpy readings(&device, &ControllerDevice::readingReady);
    QSignalSpy errors(&device, &ControllerDevice::errorOccurred);
    QSignalSpy gaps(&device, &ControllerDevice::gap);
    QSignalSpy attempts(&device, &ControllerDevice::attemptFailed);
    device.start();
    ASSERT_TRUE(test::waitFor(readings, 3));
    EXPECT_EQ(errors.count(), 0);

    test::killPeer(*peer);
    ASSERT_TRUE(test::waitFor(errors, 1));
    ASSERT_TRUE(test::waitFor(attempts, 4));
    EXPECT_EQ(errors.count(), 1) << qPrintable(errors.last().at(0).toString());
    const int before = int(readings.count());

    int same_port = 0;
    auto second = test::startControllerPeer(port, &same_port, axis);
    ASSERT_EQ(same_port, port);
    ASSERT_TRUE(test::waitFor(gaps, 1));
    ASSERT_TRUE(test::waitFor(readings, before + 3));
    EXPECT_EQ(errors.count(), 1);
    EXPECT_EQ(gaps.count(), 1);
    const auto last_before = readings.at(before - 1).at(0).value<ControllerReading>();
    const auto first_after = readings.at(before).at(0).value<ControllerReading>();
    EXPECT_EQ(gaps.at(0).at(0).toDateTime(), last_before.time_utc);
    EXPECT_EQ(gaps.at(0).at(1).toDateTime(), first_after.time_utc);
    for (const auto& args : readings) {
        const auto r = args.at(0).value<ControllerReading>();
        EXPECT_DOUBLE_EQ(r.position_mm, 250.5);
        EXPECT_DOUBLE_EQ(r.feed_mm_min, 6000.0);
        EXPECT_DOUBLE_EQ(r.torque_Nm, 3.2);
        EXPECT_EQ(r.state, MachineState::Moving);
    }
    EXPECT_TRUE(device.stopAndWait(5000));
    EXPECT_FALSE(device.isRunning());
    test::killPeer(*second);
}
