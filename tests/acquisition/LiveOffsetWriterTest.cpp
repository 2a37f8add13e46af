// The live-offset writer against the simulated controller over real Modbus
// TCP: block 3 as the register map defines it, a sequence that continues
// where the controller stands, the machine state from block 0, and offsets
// or settings the map cannot carry refused before anything is written.
#include <gtest/gtest.h>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "acquisition/live/LiveOffsetWriter.h"
#include "tests/acquisition/PushTestSupport.h"

namespace driftlab::test {
namespace {

std::int32_t liveOffsetNm(const sim::SimulatedController& c) {
    const std::uint16_t words[2] = {c.registerValue(2001), c.registerValue(2002)};
    return push::getInt32(words);
}

TEST(LiveOffsetWriter, anUpdateIsTheNextSequenceWithTheOffsetInNanometresHighWordFirst) {
    auto controller = startController();
    live::LiveOffsetWriter writer(urlOf(*controller), 1.0, 30);
    QString error;
    ASSERT_TRUE(writer.open(&error)) << qPrintable(error);
    ASSERT_TRUE(writer.publish(-19.0864, true, &error)) << qPrintable(error);
    EXPECT_EQ(controller->registerValue(2000), 1);
    EXPECT_EQ(liveOffsetNm(*controller), -19086);
    EXPECT_EQ(controller->registerValue(2001), 0xFFFF);  // −19086 = 0xFFFF B572
    EXPECT_EQ(controller->registerValue(2002), 0xB572);
    EXPECT_EQ(controller->registerValue(2003), 1);
    EXPECT_EQ(controller->registerValue(2004), 30);
    const int writes = controller->writeRequests();
    ASSERT_TRUE(writer.publish(0.5, false, &error));
    // One request per update: the controller never sees a new sequence with an old offset.
    EXPECT_EQ(controller->writeRequests(), writes + 1);
    EXPECT_EQ(controller->registerValue(2000), 2);
    EXPECT_EQ(liveOffsetNm(*controller), 500);
    EXPECT_EQ(controller->registerValue(2003), 0);
}

TEST(LiveOffsetWriter, aNewWriterContinuesTheSequenceTheControllerHolds) {
    auto controller = startController();
    QString error;
    {
        live::LiveOffsetWriter first(urlOf(*controller), 1.0, 30);
        ASSERT_TRUE(first.open(&error)) << qPrintable(error);
        for (int i = 0; i < 3; ++i) ASSERT_TRUE(first.publish(i, true, &error));
    }
    live::LiveOffsetWriter second(urlOf(*controller), 1.0, 30);
    ASSERT_TRUE(second.open(&error)) << qPrintable(error);
    EXPECT_EQ(second.sequence(), 3);
    ASSERT_TRUE(second.publish(7, true, &error));
    EXPECT_EQ(controller->registerValue(2000), 4);
}

TEST(LiveOffsetWriter, readsTheMachineStateTheControllerReports) {
    auto controller = startController();
    live::LiveOffsetWriter writer(urlOf(*controller), 1.0, 30);
    QString error;
    ASSERT_TRUE(writer.open(&error)) << qPrintable(error);
    EXPECT_EQ(writer.machineState(&error), MachineState::Idle);
    controller->setMachineState(MachineState::Cutting);
    EXPECT_EQ(writer.machineState(&error), MachineState::Cutting);
}

TEST(LiveOffsetWriter, whatTheMapCannotCarryIsRefusedBeforeAnyWrite) {
    auto controller = startController();
    QString error;
    live::LiveOffsetWriter writer(urlOf(*controller), 1.0, 30);
    ASSERT_TRUE(writer.open(&error)) << qPrintable(error);
    const int writes = controller->writeRequests();
    EXPECT_FALSE(writer.publish(3e6, true, &error));  // 3 m: beyond int32 nm
    EXPECT_TRUE(error.contains(QStringLiteral("int32 nm"))) << qPrintable(error);
    EXPECT_FALSE(writer.publish(NAN, true, &error));
    EXPECT_EQ(controller->writeRequests(), writes);
    EXPECT_EQ(controller->registerValue(2000), 0);

    live::LiveOffsetWriter noTimeout(urlOf(*controller), 1.0, 0);
    EXPECT_FALSE(noTimeout.open(&error));
    EXPECT_TRUE(error.contains(QStringLiteral("live_timeout_s"))) << qPrintable(error);
}

TEST(LiveOffsetWriter, aPortThatNeverAnswersIsNamedInTheError) {
    // A listening socket that nobody serves: the connection is made, no
    // Modbus answer ever comes.
    const int silent = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    ASSERT_EQ(bind(silent, reinterpret_cast<sockaddr*>(&address), length), 0);
    ASSERT_EQ(listen(silent, 4), 0);
    ASSERT_EQ(getsockname(silent, reinterpret_cast<sockaddr*>(&address), &length), 0);
    const int port = ntohs(address.sin_port);
    live::LiveOffsetWriter writer({QStringLiteral("127.0.0.1"), port, 1}, 0.3, 30);
    QString error;
    EXPECT_FALSE(writer.open(&error));
    EXPECT_TRUE(error.contains(QStringLiteral("127.0.0.1:%1").arg(port))) << qPrintable(error);
    close(silent);
}

}  // namespace
}  // namespace driftlab::test
