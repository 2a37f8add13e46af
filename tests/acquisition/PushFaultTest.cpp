// Faults during a push, injected by the simulated controller: a connection
// dropped at each write of the protocol, a refused commit, a register of the
// active table corrupted after applying. Each time the table that was active
// before the push is read back over Modbus, intact.
#include "tests/acquisition/PushTestSupport.h"

using namespace driftlab;
using namespace driftlab::push;
using namespace driftlab::test;

namespace {

const auto kNext = pushTable(21, 35, 6, 0.7);

/// A controller with table v1 applied; the faults come after it.
struct ControllerWithTable {
    std::unique_ptr<sim::SimulatedController> controller = startController();
    compensation::CompensationTable first = pushTable(21);

    ControllerWithTable() {
        const PushResult result = pushTable(urlOf(*controller), first, testOptions());
        EXPECT_TRUE(result.ok()) << qPrintable(result.message);
    }
    /// Pushes the next table with `faults` injected from now on.
    PushResult pushWith(const sim::ControllerFaults& faults) const {
        controller->setFaults(faults);
        return pushTable(urlOf(*controller), kNext, testOptions());
    }
    void expectFirstTableIntact() const {
        EXPECT_EQ(readActiveOverModbus(*controller), imageOf(first, 1));
        EXPECT_EQ(controller->registerValue(reg::kActiveVersion), 1);
    }
};

}  // namespace

// The writes of a push: abort leftovers, staged header, staged data, commit.
class DroppedConnection : public testing::TestWithParam<int> {};

TEST_P(DroppedConnection, reconnectsAbortsAndFindsThePreviousTableIntact) {
    ControllerWithTable setup;
    sim::ControllerFaults faults;
    faults.drop_after_writes = GetParam();
    const PushResult result = setup.pushWith(faults);
    EXPECT_EQ(result.outcome, PushOutcome::Failed);
    EXPECT_TRUE(
        result.message.contains(QStringLiteral("reconnected and aborted, the previous "
                                               "table (v1) is intact")))
        << qPrintable(result.message);
    EXPECT_TRUE(result.message.startsWith(
        QStringLiteral("127.0.0.1:%1: writing registers ").arg(setup.controller->port())))
        << qPrintable(result.message);
    EXPECT_EQ(result.previous_intact, std::optional<bool>(true));
    setup.expectFirstTableIntact();
    // Nothing staged survives to be applied by a later scan.
    EXPECT_EQ(setup.controller->registerValue(reg::kStagedHeader), 0);
}

std::string writeName(const testing::TestParamInfo<int>& info) {
    static const char* const names[] = {"abort", "header", "data", "commit"};
    return names[info.param];
}

INSTANTIATE_TEST_SUITE_P(EachWriteOfThePush, DroppedConnection, testing::Values(0, 1, 2, 3),
                         writeName);

TEST(PushFault, refusedCommitAbortsAndKeepsThePreviousTable) {
    ControllerWithTable setup;
    sim::ControllerFaults faults;
    faults.refuse_commit = true;
    const PushResult result = setup.pushWith(faults);
    EXPECT_EQ(result.outcome, PushOutcome::Refused);
    EXPECT_EQ(result.message, QStringLiteral("127.0.0.1:%1 answered 'refused by the controller' "
                                             "to table v2; aborted, the previous table (v1) is "
                                             "intact")
                                  .arg(setup.controller->port()));
    setup.expectFirstTableIntact();
}

TEST(PushFault, corruptedActiveTableIsRolledBackToThePreviousOne) {
    ControllerWithTable setup;
    sim::ControllerFaults faults;
    faults.corrupt_after_apply = true;
    const PushResult result = setup.pushWith(faults);
    EXPECT_EQ(result.outcome, PushOutcome::RolledBack);
    // The simulated fault flips a bit of the middle point (register 1100 + 10).
    EXPECT_TRUE(
        result.message.startsWith(QStringLiteral("read-back of table v2: register 1110 "
                                                 "holds 0x")))
        << qPrintable(result.message);
    EXPECT_TRUE(result.message.endsWith(
        QStringLiteral("; rolled back to the previous table (v1), read back intact")))
        << qPrintable(result.message);
    setup.expectFirstTableIntact();
    EXPECT_EQ(setup.controller->registerValue(reg::kCommitStatus),
              std::uint16_t(CommitStatus::RolledBack));
}

TEST(PushFault, corruptionOfTheFirstTableEverRollsBackToNoTable) {
    sim::SimulatedControllerOptions options;
    options.faults.corrupt_after_apply = true;
    auto controller = startController(options);
    const PushResult result = pushTable(urlOf(*controller), kNext, testOptions());
    EXPECT_EQ(result.outcome, PushOutcome::RolledBack) << qPrintable(result.message);
    EXPECT_EQ(readActiveOverModbus(*controller).version(), 0);
}
