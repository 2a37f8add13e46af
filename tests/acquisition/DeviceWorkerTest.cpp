// The polling worker on its own thread: readings arrive through queued
// signals; a peer killed mid-run gives one error however many retries fail,
// a reconnect when a new peer listens on the same port, and a gap that covers
// the outage; shutdown is bounded. All waits are bounded waits for an event.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
#include <QSignalSpy>

#include "acquisition/devices/TemperatureDevice.h"
#include "tests/acquisition/DevicePeer.h"
#include "tests/support/SignalWait.h"

using namespace driftlab;
using namespace driftlab::devices;

namespace {

DeviceWorkerOptions quickOptions() {
    DeviceWorkerOptions options;
    options.poll_interval_s = 0.05;
    options.backoff_initial_s = 0.05;
    options.backoff_max_s = 0.4;
    return options;
}

/// A port nothing listens on: bound by the system, then released.
int closedPort() {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    ::bind(fd, reinterpret_cast<sockaddr*>(&address), length);
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
    ::close(fd);
    return ntohs(address.sin_port);
}

void expectProfileValues(const TemperatureReading& r) {
    ASSERT_EQ(r.values.size(), 8u);
    EXPECT_DOUBLE_EQ(r.values[0], 21.5);
    EXPECT_DOUBLE_EQ(r.values[1], -12.3);
    EXPECT_EQ(r.status[4], ChannelStatus::InvalidRaw);
    EXPECT_DOUBLE_EQ(r.values[7], 3276.6);
}

}  // namespace

TEST(DeviceWorker, peerKilledMidRun_oneErrorReconnectOnNewPeerAndGapCoversOutage) {
    if (const QString why = test::peerUnavailable(); !why.isEmpty())
        GTEST_SKIP() << qPrintable(why);
    int port = 0;
    auto peer = test::startTemperaturePeer(0, &port);
    ASSERT_GT(port, 0);

    TemperatureDevice device(test::temperatureProfile(), {QStringLiteral("127.0.0.1"), port, 1},
                             quickOptions());
    QSignalSpy readings(&device, &TemperatureDevice::readingReady);
    QSignalSpy errors(&device, &TemperatureDevice::errorOccurred);
    QSignalSpy gaps(&device, &TemperatureDevice::gap);
    QSignalSpy attempts(&device, &TemperatureDevice::attemptFailed);
    QSignalSpy health(&device, &TemperatureDevice::healthChanged);
    device.start();
    ASSERT_TRUE(test::waitFor(readings, 3));
    EXPECT_EQ(errors.count(), 0);

    peer->kill();  // SIGKILL: no goodbye on the connection
    peer->waitForFinished();
    ASSERT_TRUE(test::waitFor(errors, 1));
    // Several failed attempts in the one cycle, still one error.
    ASSERT_TRUE(test::waitFor(attempts, 4));
    EXPECT_EQ(errors.count(), 1) << qPrintable(errors.last().at(0).toString());
    const int readings_before = int(readings.count());

    const QDateTime restarted_utc = QDateTime::currentDateTimeUtc();
    int same_port = 0;
    auto second = test::startTemperaturePeer(port, &same_port);
    ASSERT_EQ(same_port, port);
    ASSERT_TRUE(test::waitFor(gaps, 1));
    ASSERT_TRUE(test::waitFor(readings, readings_before + 3));
    EXPECT_EQ(errors.count(), 1);
    EXPECT_EQ(gaps.count(), 1);

    // The gap runs from the last reading before the kill to the first after.
    const QDateTime from = gaps.at(0).at(0).toDateTime();
    const QDateTime to = gaps.at(0).at(1).toDateTime();
    EXPECT_LT(from, restarted_utc);
    EXPECT_GE(to, restarted_utc);
    int gap_at = -1;
    for (int i = 0; i + 1 < readings.count(); ++i) {
        const auto a = readings.at(i).at(0).value<TemperatureReading>();
        const auto b = readings.at(i + 1).at(0).value<TemperatureReading>();
        if (a.time_utc == from && b.time_utc == to) gap_at = i;
    }
    EXPECT_GE(gap_at, 2) << "the gap's ends are consecutive readings";
    for (int i = 0; i < readings.count(); ++i)
        expectProfileValues(readings.at(i).at(0).value<TemperatureReading>());

    std::vector<DeviceHealth> states;
    for (const auto& args : health) states.push_back(args.at(0).value<DeviceHealth>());
    const std::vector<DeviceHealth> expected = {DeviceHealth::Connecting, DeviceHealth::Connected,
                                                DeviceHealth::Reconnecting,
                                                DeviceHealth::Connected};
    EXPECT_EQ(states, expected);

    EXPECT_TRUE(device.stopAndWait(5000));
    EXPECT_FALSE(device.isRunning());
    second->kill();
    second->waitForFinished();
}

TEST(DeviceWorker, nothingListening_oneErrorThenFailedAfterMaxAttempts) {
    DeviceWorkerOptions options = quickOptions();
    options.max_attempts = 5;
    options.backoff_max_s = 0.2;
    TemperatureDevice device(test::temperatureProfile(),
                             {QStringLiteral("127.0.0.1"), closedPort(), 1}, options);
    QSignalSpy errors(&device, &TemperatureDevice::errorOccurred);
    QSignalSpy attempts(&device, &TemperatureDevice::attemptFailed);
    QSignalSpy health(&device, &TemperatureDevice::healthChanged);
    QSignalSpy readings(&device, &TemperatureDevice::readingReady);
    device.start();
    // Failed is the last state the worker reaches on its own.
    while (health.isEmpty() || health.last().at(0).value<DeviceHealth>() != DeviceHealth::Failed)
        ASSERT_TRUE(health.wait(test::kSignalWaitMs));
    EXPECT_EQ(errors.count(), 1);
    EXPECT_TRUE(errors.at(0).at(0).toString().contains(QStringLiteral("cannot connect")));
    ASSERT_EQ(attempts.count(), 5);
    // The backoff doubles up to its cap (0.2 s); no retry after the last attempt.
    const double expected_s[] = {0.05, 0.1, 0.2, 0.2, 0.0};
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(attempts.at(i).at(0).toInt(), i + 1);
        EXPECT_DOUBLE_EQ(attempts.at(i).at(1).toDouble(), expected_s[i]);
    }
    EXPECT_EQ(readings.count(), 0);
    EXPECT_TRUE(device.stopAndWait(5000));
}

TEST(DeviceWorker, destroyedWhileRetrying_stopsWithinTheBound) {
    DeviceWorkerOptions options = quickOptions();
    options.backoff_initial_s = 5;  // the worker sits in a long backoff timer
    TemperatureDevice device(test::temperatureProfile(),
                             {QStringLiteral("127.0.0.1"), closedPort(), 1}, options);
    QSignalSpy attempts(&device, &TemperatureDevice::attemptFailed);
    device.start();
    ASSERT_TRUE(test::waitFor(attempts, 1));
    // The stop does not wait out the 5 s backoff: quit ends the timer's loop.
    EXPECT_TRUE(device.stopAndWait(4000));
    EXPECT_FALSE(device.isRunning());
    // The worker's last word, delivered through the queue.
    QSignalSpy health(&device, &TemperatureDevice::healthChanged);
    ASSERT_TRUE(health.wait(test::kSignalWaitMs));
    EXPECT_EQ(health.last().at(0).value<DeviceHealth>(), DeviceHealth::Stopped);
    device.start();  // a stopped device stays stopped (its worker is gone)
    EXPECT_FALSE(device.isRunning());
}
