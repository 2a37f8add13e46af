#include "core/rig/RigSpec.h"

namespace driftlab::rig {

std::vector<MovingStateRun> defaultMovingStates() {
    return {{QStringLiteral("S1"), 8000, {210, 490}},
            {QStringLiteral("S2"), 6500, {210, 490}},
            {QStringLiteral("S3"), 15000, {210, 490}},
            {QStringLiteral("S4"), 8000, {0, 210}},
            {QStringLiteral("S5"), 8000, {0, 700}}};
}

}  // namespace driftlab::rig
