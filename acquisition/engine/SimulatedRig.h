#pragma once
// The simulated rig behind the TestRig interface: feed-axis runs on
// rig::SimulatedAxisRun (the screw simulation, stepped), spindle and ETVE
// runs from the spindle-test simulator, played out in time. Every run has a
// seed drawn from the rig's seed in procedure order, so the same procedure
// gives the same campaign, and a resumed run replays to where it stopped.
// The spec's module outages leave the temperature columns empty and the log
// what a device rig writes for a lost module (DeviceEvents.h).

#include "acquisition/engine/TestRig.h"
#include "core/rig/RigSpec.h"

namespace driftlab::engine {

class SimulatedRig : public TestRig {
public:
    explicit SimulatedRig(rig::RigSpec spec);
    QString describe() const override;
    bool realTime() const override { return false; }
    Campaign campaignHeader(const std::vector<procedures::PlannedRun>& runs) const override;
    std::unique_ptr<RunSource> open(const procedures::PlannedRun& run, std::size_t index,
                                    const std::vector<QString>& columns, QString* error) override;

private:
    rig::RigSpec m_spec;
};

}  // namespace driftlab::engine
