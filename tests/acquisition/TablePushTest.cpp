// The push to a real Modbus TCP server (the simulated controller on
// 127.0.0.1): a table applied and read back, the wait for a safe machine
// state, a machine that never stops cutting, an unreachable controller, and
// tables refused before any register is written.
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "tests/acquisition/PushTestSupport.h"

using namespace driftlab;
using namespace driftlab::push;
using namespace driftlab::test;

namespace {

/// A port nobody listens on: bound by the system, then closed again.
int closedPort() {
    const int s = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    EXPECT_EQ(::bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    ::getsockname(s, reinterpret_cast<sockaddr*>(&address), &length);
    ::close(s);
    return ntohs(address.sin_port);
}

bool stepOk(const PushResult& result, const QString& name) {
    for (const PushStep& step : result.steps)
        if (step.name == name) return step.ok;
    return false;
}

}  // namespace

TEST(TablePush, tableIsAppliedAndReadBackEqualOverModbus) {
    auto controller = startController();
    const auto table = pushTable(21);
    const PushResult result = pushTable(urlOf(*controller), table, testOptions());
    ASSERT_EQ(result.outcome, PushOutcome::Applied) << qPrintable(result.message);
    EXPECT_EQ(result.version, 1);
    EXPECT_EQ(result.points, 21);
    EXPECT_TRUE(stepOk(result, "read_back"));
    // Another client sees the same registers in block 2 as the table encodes to.
    EXPECT_EQ(readActiveOverModbus(*controller), imageOf(table, 1));
    EXPECT_EQ(controller->registerValue(reg::kActiveVersion), 1);
    EXPECT_EQ(controller->registerValue(reg::kCommitStatus), std::uint16_t(CommitStatus::Applied));

    // The next push gets a new version and keeps the first as the previous table.
    const auto second = pushTable(21, 35, 6, 0.5);
    const PushResult again = pushTable(urlOf(*controller), second, testOptions());
    ASSERT_TRUE(again.ok()) << qPrintable(again.message);
    EXPECT_EQ(again.version, 2);
    EXPECT_EQ(again.active_before, 1);
    EXPECT_EQ(readActiveOverModbus(*controller), imageOf(second, 2));
    EXPECT_EQ(controller->registerValue(reg::kPreviousVersion), 1);
}

TEST(TablePush, bidirectionalTableIsAppliedWithItsMinusColumn) {
    auto controller = startControllerOfCapacity(64);
    auto table = pushTable(40, 17.5);
    table.bidirectional = true;
    for (double& v : table.correction_minus_um) v -= 1.5;
    const PushResult result = pushTable(urlOf(*controller), table, testOptions());
    ASSERT_TRUE(result.ok()) << qPrintable(result.message);
    EXPECT_EQ(readActiveOverModbus(*controller, 64), imageOf(table, 1, 64));
}

TEST(TablePush, cuttingMachineDelaysTheTableUntilTheCutEnds) {
    sim::SimulatedControllerOptions options;
    options.state = MachineState::Cutting;
    options.faults.idle_after_polls = 4;
    auto controller = startController(options);
    const auto table = pushTable(21);
    const PushResult result = pushTable(urlOf(*controller), table, testOptions());
    ASSERT_TRUE(result.ok()) << qPrintable(result.message);
    EXPECT_EQ(controller->registerValue(reg::kMachineState), std::uint16_t(MachineState::Idle));
    EXPECT_EQ(readActiveOverModbus(*controller), imageOf(table, 1));
}

TEST(TablePush, machineStuckCuttingTimesOutAbortsAndKeepsThePreviousTable) {
    auto controller = startController();
    const auto first = pushTable(21);
    ASSERT_TRUE(pushTable(urlOf(*controller), first, testOptions()).ok());
    controller->setMachineState(MachineState::Cutting);
    const PushResult result =
        pushTable(urlOf(*controller), pushTable(21, 35, 4, 1), testOptions(0.3));
    EXPECT_EQ(result.outcome, PushOutcome::Failed);
    EXPECT_TRUE(result.message.startsWith(
        QStringLiteral("table v2 not applied within 0.3 s (machine cutting, commit status: "
                       "staged, waiting for a safe state); aborted, the previous table (v1) is "
                       "intact")))
        << qPrintable(result.message);
    EXPECT_EQ(result.previous_intact, std::optional<bool>(true));
    EXPECT_EQ(readActiveOverModbus(*controller), imageOf(first, 1));
    EXPECT_EQ(controller->registerValue(reg::kCommitStatus), std::uint16_t(CommitStatus::Aborted));
    // The aborted table is gone: the cut ending later does not apply it.
    controller->setMachineState(MachineState::Idle);
    EXPECT_EQ(readActiveOverModbus(*controller), imageOf(first, 1));
    EXPECT_EQ(controller->applied(), 1);
}

TEST(TablePush, unreachableControllerIsAClearErrorAndNothingIsWritten) {
    const int port = closedPort();
    const PushResult result =
        pushTable({QStringLiteral("127.0.0.1"), port, 1}, pushTable(21), testOptions());
    EXPECT_EQ(result.outcome, PushOutcome::Failed);
    EXPECT_EQ(result.message, QStringLiteral("127.0.0.1:%1: cannot connect: Connection refused; "
                                             "nothing written")
                                  .arg(port));
    EXPECT_EQ(result.write_requests, 0);
}

TEST(TablePush, tableBeyondTheLimitsIsRefusedBeforeAnyWrite) {
    auto controller = startController();
    auto table = pushTable(21);
    table.correction_plus_um[5] = table.correction_minus_um[5] = 150;
    const PushResult result = pushTable(urlOf(*controller), table, testOptions());
    EXPECT_EQ(result.outcome, PushOutcome::Refused);
    EXPECT_TRUE(result.message.contains(QStringLiteral("point 5 at 175.000 mm")))
        << qPrintable(result.message);
    EXPECT_EQ(controller->writeRequests(), 0);
    EXPECT_EQ(result.write_requests, 0);
}

TEST(TablePush, tooManyPointsForTheControllerIsRefusedBeforeAnyWrite) {
    auto controller = startControllerOfCapacity(16);
    const PushResult result = pushTable(urlOf(*controller), pushTable(21), testOptions());
    EXPECT_EQ(result.outcome, PushOutcome::Refused);
    EXPECT_EQ(result.message,
              QStringLiteral("the table has 21 points; the controller at 127.0.0.1:%1 takes at "
                             "most 16: use a larger spacing; nothing written")
                  .arg(controller->port()));
    EXPECT_EQ(controller->writeRequests(), 0);
}

TEST(TablePush, changeBeyondTheLimitAgainstTheActiveTableIsRefused) {
    auto controller = startController();
    const auto first = pushTable(21);
    ASSERT_TRUE(pushTable(urlOf(*controller), first, testOptions()).ok());
    const int writesBefore = controller->writeRequests();
    auto options = testOptions();
    options.limits.max_change_um = 2;
    // Twice the amplitude: the largest change is about 8 µm.
    const PushResult result = pushTable(urlOf(*controller), pushTable(21, 35, 16), options);
    EXPECT_EQ(result.outcome, PushOutcome::Refused);
    EXPECT_TRUE(
        result.message.startsWith(QStringLiteral("against the controller's active table "
                                                 "v1: point ")))
        << qPrintable(result.message);
    EXPECT_EQ(controller->writeRequests(), writesBefore);
    // A table on other points is compared where the active one would correct.
    const PushResult resampled = pushTable(urlOf(*controller), pushTable(41, 17.5), options);
    EXPECT_EQ(resampled.outcome, PushOutcome::Refused) << qPrintable(resampled.message);
    options.limits.max_change_um = 20;
    EXPECT_TRUE(pushTable(urlOf(*controller), pushTable(21, 35, 16), options).ok());
}

TEST(TablePush, cancelBeforeWritingLeavesTheControllerUntouched) {
    auto controller = startController();
    std::atomic_bool cancel{true};
    auto options = testOptions();
    options.cancel = &cancel;
    const PushResult result = pushTable(urlOf(*controller), pushTable(21), options);
    EXPECT_EQ(result.outcome, PushOutcome::Failed);
    EXPECT_EQ(result.message, QStringLiteral("cancelled before any write"));
    EXPECT_EQ(controller->writeRequests(), 0);
}
