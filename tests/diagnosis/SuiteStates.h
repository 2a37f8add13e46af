#pragma once
// The moving states of the rig's diagnosis suites: S1, S3 and S5 (S5 held
// out), three speeds so that a speed law can be told from a gain.

#include <vector>

#include "core/rig/RigSpec.h"

namespace driftlab::test {

inline std::vector<rig::MovingStateRun> suiteStates() {
    std::vector<rig::MovingStateRun> runs;
    for (const auto& r : rig::defaultMovingStates())
        if (r.id == QLatin1String("S1") || r.id == QLatin1String("S3") ||
            r.id == QLatin1String("S5"))
            runs.push_back(r);
    return runs;
}

}  // namespace driftlab::test
